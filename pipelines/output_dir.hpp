// Output directories that never look complete when they are not, and never replace what
// is not theirs. Everything is written into a staging directory beside the final one,
// which commit() renames into place. The report.json written last (write_report in
// report.hpp) names the command that wrote the directory and every entry it holds, so a
// later run replaces a directory only when it is recognisably that command's own earlier
// output: never the current directory, one holding anything else, or another command's.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/interrupt.hpp"
#include "common/text_file.hpp"

namespace grainmesh {

class StagedOutput {
 public:
  // Creates the staging directory (and the parents of `final_dir`), after removing what
  // earlier runs into `final_dir` that were killed left (remove_stale_siblings). `kind` is
  // the command writing it ("run", "mesh", ...). Refuses, with IoError, to later replace an
  // existing `final_dir` that check_output_replaceable refuses. An interrupt removes the
  // staging directory (interrupt.hpp).
  StagedOutput(std::filesystem::path final_dir, std::string kind);
  ~StagedOutput();  // removes the staging directory unless committed or kept
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  // Where to write.
  const std::filesystem::path& dir() const { return staging_; }
  const std::filesystem::path& final_dir() const { return final_; }
  const std::string& kind() const { return kind_; }
  // Renames the staging directory to the final one, replacing an earlier output.
  void commit();
  // Where a failed run's directory is kept: FINAL.failed.
  std::filesystem::path failed_dir() const;
  // Renames the staging directory (whose report.json says it failed) to failed_dir(),
  // replacing an earlier failed output of the same kind; FINAL itself is left alone.
  void keep_as_failed();

 private:
  std::filesystem::path final_, staging_;
  std::string kind_;
  bool done_ = false;
  TemporaryPath registered_;  // the staging directory, removed on an interrupt
};

// Removes what runs into `final_dir` that were killed or interrupted left beside it: the
// hidden siblings .NAME.partial-PID and .NAME.old-PID (and NAME.failed's), where process
// PID no longer runs.
void remove_stale_siblings(const std::filesystem::path& final_dir);

// Checks, before any work is done, that `final_dir` could be written as an output of
// `kind`: it does not exist, or is an empty directory, or an earlier output of `kind`
// (its report.json says so) holding nothing but what that report lists — and, for an
// exported case, what OpenFOAM writes into it (log.*, time directories, postProcessing,
// processor*). Never the current directory or one that holds it. Throws IoError naming
// the directory and why.
void check_output_replaceable(const std::filesystem::path& final_dir, const std::string& kind);

// What a command does with its OUT before any work: checks that it could write it
// (check_output_replaceable) and removes what runs into it that were killed left beside
// it (remove_stale_siblings).
void claim_output(const std::filesystem::path& final_dir, const std::string& kind);

// A run without --solve into an OUT that holds a run solved by OpenFOAM would replace its
// answer (or its fields and stresses) with none: refused (IoError naming OUT and what to
// do) unless `force`. A run answered without --solve (the finite elements) is not.
void refuse_unsolved_over_solved(const std::filesystem::path& final_dir, bool solve, bool force);

// The keys of report.json that say which command wrote a directory and what it holds
// (written by write_report in report.hpp, read here).
inline constexpr const char* kReportCommand = "command";
inline constexpr const char* kReportFiles = "files";

}  // namespace grainmesh
