// Shared by the tests: where the sources and the binary are, scratch directories, and
// running the real grainmesh command.
#pragma once

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace grainmesh::test {

// The source tree and the grainmesh program under test (tests/paths.cpp).
std::filesystem::path source_dir();
const char* grainmesh_binary();

// Where the tests' reports are collected for the schema check that runs after them all
// (ctest's reports_match_schema): test-reports/ beside the grainmesh under test.
inline std::filesystem::path collected_reports_dir() {
  return std::filesystem::path(grainmesh_binary()).parent_path() / "test-reports";
}

// Copies every report.json under `dir` into collected_reports_dir(), each under a name of
// its own (`tag`, the process, a count, its path under `dir`).
inline void collect_reports(const std::filesystem::path& dir, const std::string& tag) {
  static int copied = 0;
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    if (it->path().filename() != "report.json" || !it->is_regular_file(ec)) continue;
    std::string name = std::filesystem::relative(it->path().parent_path(), dir, ec).string();
    std::replace(name.begin(), name.end(), '/', '_');
    std::filesystem::create_directories(collected_reports_dir(), ec);
    std::filesystem::copy_file(it->path(),
                               collected_reports_dir() / (tag + "-" + std::to_string(::getpid()) + "-" +
                                                          std::to_string(copied++) + "-" + name + ".json"),
                               std::filesystem::copy_options::overwrite_existing, ec);
  }
}

// The directory of a sweep's run of point `point` (its index in plan.json's points, in the
// lists' order) and realisation `realisation`, as the sweep's plan.json names it.
inline std::filesystem::path sweep_run(const std::filesystem::path& sweep, std::size_t point, int realisation) {
  std::ifstream in(sweep / "plan.json");
  const nlohmann::json plan = nlohmann::json::parse(in);
  for (const nlohmann::json& r : plan["runs"])
    if (r["point"].get<std::size_t>() == point && r["realisation"].get<int>() == realisation)
      return sweep / r["name"].get<std::string>();
  FAIL("plan.json has no run of point " << point << ", realisation " << realisation);
  return {};
}

// The names of a sweep's runs, as its plan.json lists them.
inline std::vector<std::string> sweep_runs(const std::filesystem::path& sweep) {
  std::ifstream in(sweep / "plan.json");
  const nlohmann::json plan = nlohmann::json::parse(in);
  std::vector<std::string> names;
  for (const nlohmann::json& r : plan["runs"]) names.push_back(r["name"].get<std::string>());
  return names;
}

inline std::filesystem::path example(const std::string& name) {
  return source_dir() / "data" / "examples" / (name + ".ini");
}

// A fresh empty directory, removed when the test ends (its reports collected first).
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& tag) : tag_(tag) {
    path_ = std::filesystem::temp_directory_path() /
            ("grainmesh-test-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter()++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  // Its reports collected for the schema check first.
  ~ScratchDir() {
    collect_reports(path_, tag_);
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  static int& counter() {
    static int c = 0;
    return c;
  }
  std::string tag_;
  std::filesystem::path path_;
};

// How many entries `dir` holds: to check that a failed run left nothing behind (no
// output, no staging directory).
inline std::size_t entries(const std::filesystem::path& dir) {
  return static_cast<std::size_t>(
      std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator{}));
}

// The regular files under `dir`, recursively, relative to it and sorted (none when it
// does not exist).
inline std::vector<std::filesystem::path> files_under(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::exists(dir))
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
      if (e.is_regular_file()) files.push_back(std::filesystem::relative(e.path(), dir));
  std::sort(files.begin(), files.end());
  return files;
}

inline std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

// Runs build/grainmesh with the arguments; captures stdout and stderr. `in` (when given)
// is the directory it runs in; `env` is put before the command (e.g. "PATH=/x:$PATH").
inline CommandResult run_grainmesh(const std::vector<std::string>& args, const std::filesystem::path& in = {},
                                   const std::string& env = {}) {
  ScratchDir io("io");
  std::string cmd = (in.empty() ? std::string() : "cd " + shell_quote(in.string()) + " && ") + env + " " +
                    shell_quote(test::grainmesh_binary());
  for (const auto& a : args) cmd.append(" ").append(shell_quote(a));
  cmd.append(" >").append(shell_quote((io / "out").string())).append(" 2>").append(shell_quote((io / "err").string()));
  const int status = std::system(cmd.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_file(io / "out");
  r.err = read_file(io / "err");
  return r;
}

// A command that must be refused: its exit code, and a fragment of its one-line error.
struct Refusal {
  std::vector<std::string> args;
  int exit_code;
  std::string says;
};

// Runs the command with `-o out` appended and checks the refusal: the exit code, one line
// on stderr holding `says`, and no `out` left behind.
inline void check_refused(const Refusal& c, const std::filesystem::path& out) {
  std::vector<std::string> args = c.args;
  args.push_back("-o");
  args.push_back(out.string());
  const auto res = run_grainmesh(args);
  INFO("args " << c.args.back() << "\nstderr: " << res.err);
  CHECK(res.exit_code == c.exit_code);
  CHECK(res.err.find(c.says) != std::string::npos);
  CHECK(std::count(res.err.begin(), res.err.end(), '\n') == 1);
  CHECK_FALSE(std::filesystem::exists(out));
}

// Runs an OpenFOAM program in a case directory (the Debian package needs WM_PROJECT_DIR);
// its output goes to CASE/log.PROGRAM. Returns the exit code (124 after 300 s) and that log.
inline CommandResult run_openfoam(const std::filesystem::path& case_dir, const std::string& program) {
  const std::filesystem::path log = case_dir / ("log." + program);
  // Bounded: a solver that does not converge must fail the test, not hang it.
  const std::string cmd = "cd " + shell_quote(case_dir.string()) + " && WM_PROJECT_DIR=/usr/share/openfoam timeout 300 " + program +
                          " > " + shell_quote(log.string()) + " 2>&1";
  const int status = std::system(cmd.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_file(log);
  return r;
}

}  // namespace grainmesh::test
