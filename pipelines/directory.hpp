// What a directory is and holds, as the commands that write directories ask it: its
// absolute path, whether it holds the current directory, its entries.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace grainmesh {

// `p` absolute, with symbolic links and "." and ".." resolved as far as it exists, without
// a trailing separator.
std::filesystem::path absolute_path(std::filesystem::path p);

// Whether `dir` is the current directory or holds it (replacing it would pull the
// ground from under the shell that started us).
bool holds_current_directory(const std::filesystem::path& dir);

// Whether an existing `dir` holds anything, so that what it holds must be checked before
// writing there: false when it does not exist or is empty. Throws IoError naming it when
// it is not a directory, or is (or holds) the current directory.
bool occupied_directory(const std::filesystem::path& dir);

// The names directly inside `dir`, sorted.
std::vector<std::string> entry_names(const std::filesystem::path& dir);

// What `dir` holds as the commands print it: its entries, sorted, separated by ", ",
// directories marked "/", the load cases (case_NAME/) listed once as case_*/.
std::string entry_list(const std::filesystem::path& dir);

}  // namespace grainmesh
