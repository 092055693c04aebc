#include "pipelines/output_dir.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <system_error>

#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "pipelines/directory.hpp"

namespace grainmesh {

namespace fs = std::filesystem;

namespace {
// A hidden sibling of `dir` named ".NAME.TAG-PID", on the same file system so that
// renames between them are atomic.
fs::path hidden_sibling(const fs::path& dir, const char* tag) {
  std::string name(".");
  name.append(dir.filename().string()).append(".").append(tag).append("-").append(std::to_string(::getpid()));
  return dir.parent_path() / name;
}

// What OpenFOAM's programs add to a case they run in: logs, time directories, function
// object output, decomposed parts.
bool openfoam_output(const std::string& name) {
  if (name.rfind("log.", 0) == 0 || name == "postProcessing" || name.rfind("processor", 0) == 0) return true;
  char* end = nullptr;
  std::strtod(name.c_str(), &end);
  return !name.empty() && std::isdigit(static_cast<unsigned char>(name[0])) && *end == '\0';
}

}  // namespace

void check_output_replaceable(const fs::path& final_dir, const std::string& kind) {
  if (!occupied_directory(final_dir)) return;
  std::error_code ec;
  const std::string where = absolute_path(final_dir).string();
  if (!fs::exists(final_dir / "report.json", ec))
    throw IoError(where + ": exists and is not a grainmesh output (no report.json); refusing to replace it");
  nlohmann::json report;
  try {
    report = nlohmann::json::parse(read_text_file(final_dir / "report.json"));
  } catch (const nlohmann::json::exception&) {
    throw IoError(where + ": its report.json is damaged; refusing to replace it");
  }
  const auto command = report.is_object() ? report.find(kReportCommand) : report.end();
  if (command == report.end() || !command->is_string() || *command != kind)
    throw IoError(where + ": is not the output of grainmesh " + kind +
                  (command != report.end() && command->is_string() ? " but of grainmesh " + command->get<std::string>()
                                                                   : std::string()) +
                  "; refusing to replace it");
  std::set<std::string> written;
  const auto files = report.find(kReportFiles);
  if (files == report.end() || !files->is_array())
    throw IoError(where + ": was written by an earlier grainmesh, whose report.json lists no files; remove it yourself "
                          "to replace it");
  for (const auto& f : *files)
    if (f.is_string()) written.insert(f.get<std::string>());
  for (const std::string& name : entry_names(final_dir))
    if (!written.count(name) && !(kind == "export" && openfoam_output(name)))
      throw IoError(where + ": holds '" + name + "', which grainmesh " + kind +
                    " did not write; refusing to replace it (move it away, or give a new directory)");
}

void remove_stale_siblings(const fs::path& final_dir) {
  const fs::path dir = absolute_path(final_dir);
  const std::string name = dir.filename().string();
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir.parent_path(), ec)) {
    const std::string sibling = entry.path().filename().string();
    for (const std::string& of : {"." + name + ".", "." + name + ".failed."})
      for (const char* tag : {"partial-", "old-"}) {
        const std::string prefix = of + tag;
        if (sibling.rfind(prefix, 0) != 0) continue;
        const std::string pid = sibling.substr(prefix.size());
        if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
        if (::kill(static_cast<pid_t>(std::stol(pid)), 0) == 0 || errno != ESRCH) continue;  // it still runs
        fs::remove_all(entry.path(), ec);
      }
  }
}

void refuse_unsolved_over_solved(const fs::path& final_dir, bool solve, bool force) {
  if (solve || force) return;
  std::error_code ec;
  if (!fs::exists(final_dir / "report.json", ec)) return;
  bool solved = false;
  try {
    const nlohmann::json report = nlohmann::json::parse(read_text_file(final_dir / "report.json"));
    // Solved by OpenFOAM (`solved`; reports before it: any answer). A periodic cell's finite
    // elements answer without --solve too: such a run is replaced by its like.
    solved = report.is_object() && report.value(kReportCommand, "") == "run" &&
             report.value("solved", report.contains("effective"));
  } catch (const std::exception&) {
    return;  // not a report this check can read: claim_output judges the directory
  }
  if (solved)
    throw IoError(absolute_path(final_dir).string() + ": holds a solved run, whose answer a run without --solve would "
                  "replace with none: add --solve, give another OUT, or --force to replace it");
}

void claim_output(const fs::path& final_dir, const std::string& kind) {
  check_output_replaceable(final_dir, kind);
  remove_stale_siblings(final_dir);
}

StagedOutput::StagedOutput(fs::path final_dir, std::string kind) : final_(absolute_path(final_dir)), kind_(std::move(kind)) {
  check_output_replaceable(final_, kind_);
  const fs::path parent = final_.parent_path();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw IoError(parent.string() + ": cannot create directory: " + ec.message());
  remove_stale_siblings(final_);
  staging_ = hidden_sibling(final_, "partial");
  registered_ = TemporaryPath(staging_);
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec) || ec)
    throw IoError(staging_.string() + ": cannot create directory: " + ec.message());
}

StagedOutput::~StagedOutput() {
  if (done_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

namespace {
// Renames `from` to `to`, replacing `to` (which check_output_replaceable allowed).
void move_into_place(const fs::path& from, const fs::path& to, const std::string& kind) {
  std::error_code ec;
  fs::path old;
  if (fs::exists(to, ec)) {
    check_output_replaceable(to, kind);
    // Not removed on an interrupt: between the two renames it is the only output there
    // is (the next run into `to` removes it, remove_stale_siblings).
    old = hidden_sibling(to, "old");
    fs::remove_all(old, ec);
    fs::rename(to, old, ec);
    if (ec) throw IoError(to.string() + ": cannot move the earlier output aside: " + ec.message());
  }
  fs::rename(from, to, ec);
  if (ec) throw IoError(to.string() + ": cannot move the output into place: " + ec.message());
  if (!old.empty()) fs::remove_all(old, ec);
}
}  // namespace

void StagedOutput::commit() {
  move_into_place(staging_, final_, kind_);
  registered_.release();
  done_ = true;
}

fs::path StagedOutput::failed_dir() const { return final_.parent_path() / (final_.filename().string() + ".failed"); }

void StagedOutput::keep_as_failed() {
  move_into_place(staging_, failed_dir(), kind_);
  registered_.release();
  done_ = true;
}

}  // namespace grainmesh
