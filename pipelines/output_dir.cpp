#include "pipelines/output_dir.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "common/errors.hpp"

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
}  // namespace

void check_output_replaceable(const fs::path& final_dir, Replace policy) {
  std::error_code ec;
  if (!fs::exists(final_dir, ec)) return;
  if (!fs::is_directory(final_dir, ec))
    throw IoError(final_dir.string() + ": exists and is not a directory");
  if (policy == Replace::anything || fs::is_empty(final_dir, ec)) return;
  if (policy == Replace::empty_only)
    throw IoError(final_dir.string() + ": exists and is not empty; use --force to replace it");
  if (!fs::exists(final_dir / "report.json", ec))
    throw IoError(final_dir.string() + ": exists and is not a grainmesh output (no report.json); refusing to replace it");
}

StagedOutput::StagedOutput(fs::path final_dir, Replace policy)
    : final_(fs::absolute(std::move(final_dir)).lexically_normal()), policy_(policy) {
  if (final_.filename().empty()) final_ = final_.parent_path();
  check_output_replaceable(final_, policy_);
  const fs::path parent = final_.parent_path();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw IoError(parent.string() + ": cannot create directory: " + ec.message());
  staging_ = hidden_sibling(final_, "partial");
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec) || ec)
    throw IoError(staging_.string() + ": cannot create directory: " + ec.message());
}

StagedOutput::~StagedOutput() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

void StagedOutput::commit() {
  std::error_code ec;
  fs::path old;
  if (fs::exists(final_, ec)) {
    check_output_replaceable(final_, policy_);
    old = hidden_sibling(final_, "old");
    fs::remove_all(old, ec);
    fs::rename(final_, old, ec);
    if (ec) throw IoError(final_.string() + ": cannot move the earlier output aside: " + ec.message());
  }
  fs::rename(staging_, final_, ec);
  if (ec) throw IoError(final_.string() + ": cannot move the output into place: " + ec.message());
  committed_ = true;
  if (!old.empty()) fs::remove_all(old, ec);
}

std::string read_text_file(const fs::path& file, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(file.string() + ": cannot open " + what);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text_file(const fs::path& file, const std::string& text) {
  const fs::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.flush();
    if (!out) throw IoError(file.string() + ": cannot write");
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) throw IoError(file.string() + ": cannot write: " + ec.message());
}

}  // namespace grainmesh
