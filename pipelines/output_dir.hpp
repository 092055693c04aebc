// Output directories that never look complete when they are not: everything is written
// into a staging directory beside the final one, which commit() renames into place.
#pragma once

#include <filesystem>
#include <string>

namespace grainmesh {

// Which existing output directory may be replaced.
enum class Replace {
  earlier_output,  // an empty one, or one holding a report.json (an earlier grainmesh output)
  empty_only,      // an empty one only
  anything,        // any directory (--force)
};

class StagedOutput {
 public:
  // Creates the staging directory (and the parents of `final_dir`). Refuses, with
  // IoError, to later replace an existing `final_dir` that is not a directory, or that
  // the policy does not allow to replace.
  explicit StagedOutput(std::filesystem::path final_dir, Replace policy = Replace::earlier_output);
  ~StagedOutput();  // removes the staging directory unless committed
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  // Where to write.
  const std::filesystem::path& dir() const { return staging_; }
  // Renames the staging directory to the final one, replacing an earlier output.
  void commit();

 private:
  std::filesystem::path final_, staging_;
  Replace policy_;
  bool committed_ = false;
};

// Checks, before any work is done, that `final_dir` could be replaced (see above).
void check_output_replaceable(const std::filesystem::path& final_dir, Replace policy = Replace::earlier_output);

// The whole of `file`; IoError "FILE: cannot open WHAT" when it cannot be read.
std::string read_text_file(const std::filesystem::path& file, const std::string& what = "file");

// Writes `text` to `file` through a temporary file and a rename. Throws IoError.
void write_text_file(const std::filesystem::path& file, const std::string& text);

}  // namespace grainmesh
