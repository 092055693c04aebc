// Runs that must end and never lie: the wall-clock limit (limits.seconds) stops a case
// that cannot converge, and `run` and `sweep` killed by SIGKILL at random moments leave
// no output that looks complete, while a resumed sweep finishes with the same results as
// one never interrupted.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <random>
#include <thread>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "helpers.hpp"

using namespace grainmesh;
using test::run_grainmesh;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

extern char** environ;

namespace {

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// grainmesh with `args`, not waited for: its stdout discarded, its stderr into `err` (or
// discarded), `env` (NAME=value) added to its environment.
pid_t spawn_grainmesh(const std::vector<std::string>& args, const fs::path& err = {},
                      const std::vector<std::string>& env = {}) {
  std::vector<std::string> all{test::grainmesh_binary()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> variables = env;
  for (char** e = environ; *e != nullptr; ++e) variables.emplace_back(*e);  // the first of a name wins
  std::vector<char*> envp;
  for (auto& v : variables) envp.push_back(v.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t io;
  posix_spawn_file_actions_init(&io);
  posix_spawn_file_actions_addopen(&io, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&io, 2, err.empty() ? "/dev/null" : err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, test::grainmesh_binary(), &io, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&io);
  REQUIRE(rc == 0);
  return pid;
}

// Sends `pid` `signal` after `delay` seconds (nothing when it has ended by then) and waits
// for it; its wait status, and whether the signal was sent.
std::pair<int, bool> signalled_after(pid_t pid, int signal, double delay) {
  const auto t0 = Clock::now();
  int status = 0;
  while (seconds_since(t0) < delay) {
    if (waitpid(pid, &status, WNOHANG) == pid) return {status, false};
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(pid, signal);
  waitpid(pid, &status, 0);
  return {status, true};
}
int signal_after(pid_t pid, int signal, double delay) { return signalled_after(pid, signal, delay).first; }

// Kills `pid` with SIGKILL after `delay` seconds (at once when it has already ended);
// true when it was still running.
bool kill_after(pid_t pid, double delay) { return signalled_after(pid, SIGKILL, delay).second; }

// Waits (up to 10 s) until process `pid` handles interrupts: install_interrupt_handling
// has caught its threads' freeze signal (SIGRTMIN + 3, common/interrupt.cpp), seen in
// /proc's SigCgt. False when it ended or never did.
bool wait_for_interrupt_handling(pid_t pid) {
  const unsigned long long bit = 1ULL << (SIGRTMIN + 3 - 1);
  for (const auto t0 = Clock::now(); seconds_since(t0) < 10.0;) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("SigCgt:", 0) == 0 && (std::stoull(line.substr(7), nullptr, 16) & bit) != 0) return true;
    int ended = 0;
    if (waitpid(pid, &ended, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return false;
}

// The names `dir` holds, for a failure's message.
std::string names_in(const fs::path& dir) {
  std::string names;
  for (const auto& e : fs::directory_iterator(dir)) names += e.path().filename().string() + " ";
  return names;
}

// Processes whose command line mentions `dir`, or which run in it or below (children that
// outlived their parent: TetGen's helpers and the solver run in directories of the output's staging
// or the temporary directory, which never appear on their command lines).
int processes_in(const fs::path& dir) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos || name == std::to_string(getpid())) continue;
    std::string cmdline = test::read_file(entry.path() / "cmdline");
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    std::error_code ec;
    const std::string cwd = fs::read_symlink(entry.path() / "cwd", ec).string();
    if (cmdline.find(dir.string()) != std::string::npos || (!ec && cwd.rfind(dir.string(), 0) == 0)) ++n;
  }
  return n;
}

// The solvers (solidDisplacementFoam: /proc's comm holds its first 15 characters) running
// in `dir` or below.
std::vector<pid_t> solvers_in(const fs::path& dir) {
  std::vector<pid_t> pids;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::error_code ec;
    const std::string cwd = fs::read_symlink(entry.path() / "cwd", ec).string();
    if (ec || cwd.rfind(dir.string(), 0) != 0) continue;
    if (test::read_file(entry.path() / "comm").rfind("solidDisplaceme", 0) == 0) pids.push_back(std::stoi(name));
  }
  return pids;
}

// Whether `pid` runs (a zombie left for a parent that does not reap it does not).
bool running(pid_t pid) {
  const fs::path stat = "/proc/" + std::to_string(pid) + "/stat";
  if (!fs::exists(stat)) return false;
  const std::string text = test::read_file(stat);
  const auto paren = text.rfind(')');
  return paren != std::string::npos && paren + 2 < text.size() && text[paren + 2] != 'Z';
}

// A report without the figures that differ between identical runs (timings, memory).
nlohmann::json stable(nlohmann::json report) {
  report.erase("seconds");
  report.erase("memory_mib");
  report.erase("peak_memory_mib");
  if (report.contains("effective")) {
    nlohmann::json& effective = report["effective"];
    effective.erase("seconds");  // OpenFOAM's steps
    if (effective.contains("load_cases"))
      for (nlohmann::json& c : effective["load_cases"]) c.erase("seconds");
  }
  return report;
}

}  // namespace

TEST_CASE("limits.seconds: a case that cannot converge ends at its bound with exit 5 and nothing written",
          "[cli][limits]") {
  test::ScratchDir dir("limit");
  {
    // DistMesh with a convergence tolerance no mesh can meet and no iteration bound to
    // speak of: only the clock stops it.
    std::ofstream(dir / "stuck.ini") << "[domain]\nshape = circle(0, 0, 1)\n[size]\nh0 = 0.02\n"
                                        "[distmesh]\ndptol = 1e-300\nmax_iterations = 100000000\n"
                                        "[limits]\nseconds = 2\n";
  }
  const auto t0 = Clock::now();
  const auto r = run_grainmesh({"domain", (dir / "stuck.ini").string(), "-o", (dir / "out").string()});
  const double took = seconds_since(t0);
  INFO(r.err);
  CHECK(r.exit_code == 5);
  CHECK(took < 2.0 + 8.0);  // the limit, the start-up and (sanitized) slowness
  CHECK(r.err.find("limits.seconds = 2 s reached") != std::string::npos);
  CHECK(r.err.find("raise it") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(dir / "out"));
  CHECK(test::entries(dir.path()) == 1);  // no staging directory left either

  // The whole pipeline under one limit: 20,000 grains cannot be meshed in a second.
  const auto t1 = Clock::now();
  const auto big = run_grainmesh({"run", "-o", (dir / "big").string(), "--set", "tessellation.grains=20000",
                                  "--set", "limits.seconds=1"});
  INFO(big.err);
  CHECK(big.exit_code == 5);
  CHECK(seconds_since(t1) < 1.0 + 8.0);
  CHECK(big.err.find("limits.seconds = 1 s reached") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "big"));

  // A run within its limit reports the limit it ran under.
  const auto ok = run_grainmesh({"run", "-o", (dir / "ok").string(), "--set", "limits.seconds=600"});
  REQUIRE(ok.exit_code == 0);
  CHECK(nlohmann::json::parse(test::read_file(dir / "ok/report.json"))["time_limit_seconds"] == 600.0);
  const auto bad = run_grainmesh({"run", "-o", (dir / "bad").string(), "--set", "limits.seconds=-1"});
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("limits.seconds") != std::string::npos);
}

TEST_CASE("grainmesh run killed at random moments never leaves an output that looks complete", "[cli][kill]") {
  test::ScratchDir dir("kill-run");
  const std::vector<std::string> args{"run", "-o", (dir / "out").string(), "--solve", "--set", "tessellation.grains=40"};

  // The uninterrupted run: how long it takes and what it writes.
  const auto t0 = Clock::now();
  const auto whole = run_grainmesh(args);
  const double full = seconds_since(t0);
  REQUIRE(whole.exit_code == 0);
  const std::vector<fs::path> complete = test::files_under(dir / "out");
  const nlohmann::json expected = stable(nlohmann::json::parse(test::read_file(dir / "out/report.json")));
  fs::remove_all(dir / "out");

  std::mt19937_64 rng(8);  // the kill times, reproducible
  // (Half the trials in the sanitizer build, where each run takes four times as long.)
#ifdef GRAINMESH_SANITIZED
  const int trials = 4;
#else
  const int trials = 8;
#endif
  // A run can finish before its kill time (later runs are often faster than the timed
  // first one): then more trials, up to twice as many, until half of them interrupted one.
  int interrupted = 0;
  for (int trial = 0; trial < 2 * trials && (trial < trials || interrupted < trials / 2); ++trial) {
    const double at = std::uniform_real_distribution<double>(0.0, full)(rng);
    INFO("trial " << trial << ": killed after " << at << " s of " << full);
    if (kill_after(spawn_grainmesh(args), at)) ++interrupted;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    CHECK(processes_in(dir.path()) == 0);  // the solver died with it
    if (fs::exists(dir / "out")) {
      // Present only as a whole: every file, the same report.
      CHECK(test::files_under(dir / "out") == complete);
      CHECK(stable(nlohmann::json::parse(test::read_file(dir / "out/report.json"))) == expected);
    }
    // Whatever was staged is marked as such; the next run replaces it all.
    for (const auto& e : fs::directory_iterator(dir.path()))
      if (e.path().filename() != "out") CHECK(e.path().filename().string().find(".partial-") != std::string::npos);
    fs::remove_all(dir / "out");
  }
  CHECK(interrupted >= trials / 2);

  // Killed while its solver runs (seen running first, so this part cannot pass unseen):
  // the solver goes with it.
  const pid_t pid = spawn_grainmesh(args);
  std::vector<pid_t> solvers;
  for (const auto t1 = Clock::now(); solvers.empty() && seconds_since(t1) < 4 * full;)
    if (solvers = solvers_in(dir.path()); solvers.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  REQUIRE_FALSE(solvers.empty());
  kill_after(pid, 0.0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  for (const pid_t solver : solvers) CHECK_FALSE(running(solver));
  CHECK(processes_in(dir.path()) == 0);
}

TEST_CASE("grainmesh sweep killed at random moments resumes to the results of an uninterrupted sweep",
          "[cli][kill][sweep]") {
  test::ScratchDir dir("kill-sweep");
  {
    std::ofstream out(dir / "sweep.ini");
    out << test::read_file(test::source_dir() / "data/default.ini")
        << "\n[sweep]\ntessellation.grains = 20, 30\nphase.matrix.fraction = 0.1, 0.3\nrealisations = 2\n";
  }
  auto sweep_args = [&](const std::string& out) {
    return std::vector<std::string>{"sweep", (dir / "sweep.ini").string(), "-o", (dir / out).string(), "--jobs", "2"};
  };
  const auto t0 = Clock::now();
  REQUIRE(run_grainmesh(sweep_args("reference")).exit_code == 0);
  const double full = seconds_since(t0);

  std::mt19937_64 rng(9);
  for (int trial = 0; trial < 4; ++trial) {
    const double at = std::uniform_real_distribution<double>(0.1 * full, 0.9 * full)(rng);
    INFO("trial " << trial << ": killed after " << at << " s of " << full);
    kill_after(spawn_grainmesh(sweep_args("out")), at);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    CHECK(processes_in(dir.path()) == 0);  // its runs died with it
    // Every run directory that looks done is done: the reference's files, the same report.
    if (fs::exists(dir / "out"))
      for (const auto& e : fs::directory_iterator(dir / "out")) {
        const std::string name = e.path().filename().string();
        if (!e.is_directory() || name == "logs" || name == "retired") continue;
        if (!fs::exists(e.path() / "report.json")) continue;
        CHECK(test::files_under(e.path()) == test::files_under(dir / "reference" / name));
      }
  }
  // Resumed: every run there, each as in the uninterrupted sweep.
  const auto rest = run_grainmesh(sweep_args("out"));
  INFO(rest.out << rest.err);
  REQUIRE(rest.exit_code == 0);
  int runs = 0;
  for (const auto& e : fs::directory_iterator(dir / "reference")) {
    const std::string name = e.path().filename().string();
    if (!e.is_directory() || name == "logs" || name == "retired") continue;
    ++runs;
    INFO(name);
    REQUIRE(fs::exists(dir / "out" / name / "report.json"));
    CHECK(stable(nlohmann::json::parse(test::read_file(dir / "out" / name / "report.json"))) ==
          stable(nlohmann::json::parse(test::read_file(e.path() / "report.json"))));
    CHECK(test::read_file(dir / "out" / name / "mesh.vtu") == test::read_file(e.path() / "mesh.vtu"));
  }
  CHECK(runs == 8);
  for (const auto& e : fs::directory_iterator(dir / "out"))
    CHECK(e.path().filename().string().find(".partial-") == std::string::npos);
}

TEST_CASE("grainmesh run interrupted (Ctrl-C, SIGTERM) at random moments says so in one line and leaves nothing",
          "[cli][interrupt]") {
  // A 3D periodic cell solved: TetGen's helpers, the solver in
  // the staging directory, both to be cleaned up.
  test::ScratchDir dir("interrupt-run");
  const fs::path tmp = dir / "tmp";
  fs::create_directories(tmp);
#ifdef GRAINMESH_SANITIZED
  const char* grains = "8";  // the point there is memory, not the cell's size (44 -> 30 s)
#else
  const char* grains = "12";
#endif
  {
    std::ofstream(dir / "cell.ini") << "[domain]\nwidth = 1\nheight = 1\ndepth = 1\nperiodic = true\n"
                                       "[tessellation]\ngrains = " << grains << "\nseed = 5\nlloyd_iterations = 3\n"
                                       "[phase.WC]\nfraction = rest\nE = 700e9\nnu = 0.2\n"
                                       "[phase.Co]\nfraction = 0.2\nE = 210e9\nnu = 0.3\n"
                                       "[mesh]\ntets_per_grain = 150\n[homogenise]\nboundary = periodic\n"
                                       "[output]\npictures = none\n";
  }
  const fs::path out = dir / "out";
  const std::vector<std::string> args{"run", (dir / "cell.ini").string(), "-o", out.string(), "--solve", "--quiet"};
  const std::vector<std::string> env{"TMPDIR=" + tmp.string()};
  const auto t0 = Clock::now();
  REQUIRE(signal_after(spawn_grainmesh(args, dir / "err", env), SIGKILL, 600.0) == 0);
  const double full = seconds_since(t0);
  fs::remove_all(out);
  // What an earlier run killed outright (SIGKILL: no handler can clean up) left beside OUT.
  fs::create_directories(dir / ".out.partial-999999999/case_xx");
  std::mt19937_64 rng(11);
  int interrupted = 0;
#ifdef GRAINMESH_SANITIZED
  const int trials = 3;  // the point there is memory, not coverage of moments
#else
  const int trials = 5;
#endif
  for (int trial = 0; trial < trials; ++trial) {
    const int signal = trial % 2 == 0 ? SIGINT : SIGTERM;
    const double at = std::uniform_real_distribution<double>(0.05, 0.95)(rng) * full;
    INFO("trial " << trial << ": signal " << signal << " after " << at << " s of " << full);
    const int status = signal_after(spawn_grainmesh(args, dir / "err", env), signal, at);
    const std::string err = test::read_file(dir / "err");
    INFO(err);
    REQUIRE(WIFEXITED(status));
    if (WEXITSTATUS(status) == 0) {
      CHECK(fs::exists(out / "report.json"));  // finished before the signal came
    } else {
      ++interrupted;
      CHECK(WEXITSTATUS(status) == 128 + signal);
      CHECK(err.find("grainmesh: interrupted; nothing written to " + out.string() + "\n") != std::string::npos);
      CHECK(err.find("error") == std::string::npos);
      CHECK_FALSE(fs::exists(out));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    CHECK(processes_in(dir.path()) == 0);  // TetGen and the solver stopped with it
    INFO("left in the temporary directory: " << names_in(tmp));
    CHECK(test::entries(tmp) == 0);  // nothing left in the temporary directory
    for (const auto& e : fs::directory_iterator(dir.path())) {  // no staging left, the stale one removed
      const std::string name = e.path().filename().string();
      CHECK((name == "out" || name == "tmp" || name == "err" || name == "cell.ini"));
    }
    fs::remove_all(out);
  }
  CHECK(interrupted >= trials - 2);
  // At its very start: in the loader (the signal's default action, before anything is
  // written), in the libraries' constructors (OpenBLAS starts its threads there), in main
  // before and after the interrupt's thread starts. Ended by the signal or by its handling,
  // it leaves nothing and no process behind; from the moment its handling is installed, it
  // is handled.
  auto leaves_nothing = [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    CHECK(processes_in(dir.path()) == 0);
    INFO("left in the temporary directory: " << names_in(tmp));
    CHECK(test::entries(tmp) == 0);
    for (const auto& e : fs::directory_iterator(dir.path())) {
      const std::string name = e.path().filename().string();
      CHECK((name == "tmp" || name == "err" || name == "cell.ini"));
    }
  };
  for (const double at : {0.0, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2}) {
    const int status = signal_after(spawn_grainmesh(args, dir / "err", env), SIGINT, at);
    INFO("SIGINT after " << at << " s: " << test::read_file(dir / "err"));
    if (WIFSIGNALED(status))
      CHECK(WTERMSIG(status) == SIGINT);
    else
      CHECK(WEXITSTATUS(status) == 130);
    leaves_nothing();
  }
  for (int trial = 0; trial < 3; ++trial) {
    const pid_t pid = spawn_grainmesh(args, dir / "err", env);
    REQUIRE(wait_for_interrupt_handling(pid));
    const int status = signal_after(pid, SIGINT, 0.0);
    INFO("SIGINT as the handling is installed: " << test::read_file(dir / "err"));
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 130);
    leaves_nothing();
  }
  // The next run succeeds.
  CHECK(signal_after(spawn_grainmesh(args, dir / "err", env), SIGKILL, 600.0) == 0);
  CHECK(fs::exists(out / "report.json"));
}

TEST_CASE("grainmesh sweep interrupted at random moments keeps its finished runs, leaves no partial one, and resumes",
          "[cli][interrupt][sweep]") {
  test::ScratchDir dir("interrupt-sweep");
  {
    std::ofstream(dir / "sweep.ini") << test::read_file(test::source_dir() / "data/default.ini")
                                     << "\n[output]\npictures = none\n[sweep]\ntessellation.grains = 20, 30\nrealisations = 2\n";
  }
  const fs::path out = dir / "out";
  const std::vector<std::string> args{"sweep", (dir / "sweep.ini").string(), "-o", out.string(), "--solve", "--jobs", "2"};
  const auto t0 = Clock::now();
  REQUIRE(signal_after(spawn_grainmesh(args, dir / "err"), SIGKILL, 600.0) == 0);
  const double full = seconds_since(t0);
  // Interrupted as its first runs start (the moment its plan is written): a run that has
  // just been forked reports its interrupt in its log, never on the sweep's stderr.
  for (int trial = 0; trial < 4; ++trial) {
    fs::remove_all(out);
    const pid_t pid = spawn_grainmesh(args, dir / "err");
    for (const auto since = Clock::now(); !fs::exists(out / "plan.json") && seconds_since(since) < 60.0;)
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    const int status = signal_after(pid, SIGINT, 0.002 * trial);
    const std::string err = test::read_file(dir / "err");
    INFO("trial " << trial << " as the runs start: " << err);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 130);
    CHECK(err == "grainmesh: interrupted; the runs that finished are kept in " + out.string() +
                     "; run the sweep again to finish it\n");
  }
  fs::remove_all(out);
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 3; ++trial) {
    const double at = std::uniform_real_distribution<double>(0.1, 0.9)(rng) * full;
    INFO("trial " << trial << ": interrupted after " << at << " s of " << full);
    const int status = signal_after(spawn_grainmesh(args, dir / "err"), SIGINT, at);
    const std::string err = test::read_file(dir / "err");
    INFO(err);
    REQUIRE(WIFEXITED(status));
    if (WEXITSTATUS(status) != 0) {
      CHECK(WEXITSTATUS(status) == 130);
      CHECK(err == "grainmesh: interrupted; the runs that finished are kept in " + out.string() +
                       "; run the sweep again to finish it\n");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    CHECK(processes_in(dir.path()) == 0);
    // Every run directory there is complete (a report); nothing staged is left.
    if (fs::exists(out))
      for (const auto& e : fs::directory_iterator(out)) {
        const std::string name = e.path().filename().string();
        CHECK(name.find(".partial-") == std::string::npos);
        if (e.is_directory() && name != "logs") CHECK(fs::exists(e.path() / "report.json"));
      }
  }
  const auto rest = run_grainmesh(args);
  INFO(rest.err);
  CHECK(rest.exit_code == 0);
  for (const char* run : {"grains=20-r00", "grains=20-r01", "grains=30-r00", "grains=30-r01"})
    CHECK(fs::exists(out / run / "report.json"));
}
