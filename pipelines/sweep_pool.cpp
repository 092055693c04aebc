#include "pipelines/sweep_pool.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "analysis/fe_homogenise.hpp"
#include "common/process.hpp"
#include "pipelines/run_command.hpp"

namespace grainmesh {
namespace {

// Why a run ended as it did (its wait status): its log's error line, or its last line,
// or the signal that ended it.
std::string run_failure(const std::filesystem::path& log, int status) {
  std::ifstream in(log);
  std::string last;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(kErrorPrefix, 0) == 0) return line.substr(kErrorPrefix.size());
    if (!trimmed(line).empty()) last = trimmed(line);
  }
  if (WIFSIGNALED(status)) return "ended by signal " + std::to_string(WTERMSIG(status)) + (last.empty() ? "" : " after \"" + last + "\"");
  return last.empty() ? "exit code " + std::to_string(WEXITSTATUS(status)) : last;
}

}  // namespace

PoolResult run_pool(const std::vector<const SweepRun*>& todo, const SweepPlan& plan, const std::string& source,
                    const std::filesystem::path& dir, const SweepOptions& o) {
  const bool terminal = isatty(STDERR_FILENO) != 0;
  const auto start = std::chrono::steady_clock::now();
  std::size_t done = 0, next = 0;
  PoolResult result;
  std::map<pid_t, const SweepRun*> running;
  // On an interrupt each run gets SIGTERM and removes its own staging directory.
  std::map<pid_t, std::unique_ptr<RegisteredChild>> registered;
  auto progress = [&] {
    if (!terminal) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double left = done > 0 ? elapsed / static_cast<double>(done) * static_cast<double>(todo.size() - done) : 0.0;
    std::fprintf(stderr, "\rgrainmesh sweep: %zu / %zu runs, %.0f s elapsed, ~%.0f s left   ", done, todo.size(),
                 elapsed, left);
    std::fflush(stderr);
  };
  std::fflush(stdout);
  while (next < todo.size() || !running.empty()) {
    while (next < todo.size() && static_cast<int>(running.size()) < o.jobs) {
      const SweepRun* r = todo[next++];
      const pid_t parent = getpid();
      auto child = std::make_unique<RegisteredChild>(true);
      const pid_t pid = child->pid();
      if (pid < 0) throw IoError("sweep: cannot start a run (fork failed)");
      if (pid == 0) {
        // A killed sweep takes its runs with it: none finishes behind a resumed sweep's back,
        // and each removes what it was writing (SIGTERM, handled as an interrupt).
        die_with_parent(parent, SIGTERM);
        // The run: its output to its log, its errors as its exit code. Its output goes there
        // before its interrupt handling starts (the signals stay blocked until then), so an
        // interrupt it reports is in its log, and the sweep's line is the only one on stderr.
        if (!std::freopen((dir / "logs" / (r->name + ".log")).c_str(), "w", stdout)) _exit(4);
        dup2(STDOUT_FILENO, STDERR_FILENO);
        install_interrupt_handling("nothing written to " + (dir / r->name).string());
        if (o.jobs > 1) limit_fe_threads(1);  // the runs share the cores
        int code = 0;
        try {
          run_run_command(Config::from_text(plan.base_text, source, r->overrides), dir / r->name, o.solve, true);
        } catch (const std::exception& e) {
          wait_if_interrupted();
          std::printf("%s%s\n", kErrorPrefix.data(), e.what());
          code = exit_code_of(e);
        }
        std::fflush(stdout);
        _exit(code);
      }
      running[pid] = r;
      registered[pid] = std::move(child);
    }
    progress();
    int status = 0;
    const pid_t pid = wait(&status);
    if (pid < 0) {
      wait_if_interrupted();  // the interrupt's thread reaped them
      break;
    }
    registered.erase(pid);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      const std::string& name = running[pid]->name;
      result.failed[name] = WIFEXITED(status) ? WEXITSTATUS(status) : kExitInternal;
      if (result.first_failed.empty()) {
        result.first_failed = name;
        result.first_failure = run_failure(dir / "logs" / (name + ".log"), status);
      }
    }
    running.erase(pid);
    ++done;
  }
  progress();
  if (terminal) std::fprintf(stderr, "\n");
  return result;
}


}  // namespace grainmesh
