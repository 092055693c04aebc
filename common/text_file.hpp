// Whole files as text: read in one piece, written through a temporary file and a rename.
#pragma once

#include <filesystem>
#include <string>

namespace grainmesh {

// The whole of `file`; IoError "FILE: cannot open WHAT" when it cannot be read.
std::string read_text_file(const std::filesystem::path& file, const std::string& what = "file");

// Writes `text` to `file` through a temporary file and a rename. Throws IoError.
void write_text_file(const std::filesystem::path& file, const std::string& text);

}  // namespace grainmesh
