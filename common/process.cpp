#include "common/process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <thread>

#include "common/errors.hpp"
#include "common/interrupt.hpp"

namespace grainmesh {

void die_with_parent(pid_t parent, int signal) {
  prctl(PR_SET_PDEATHSIG, signal);
  if (getppid() != parent) _exit(128 + signal);  // it died before the line above
}

namespace {

// A child's environment: this process's with `environment` (NAME=value) added, replacing
// variables of the same name. Built before fork: the child may only exec.
std::vector<std::string> child_environment(const std::vector<std::string>& environment) {
  std::vector<std::string> variables = environment;
  auto replaced = [&](std::string_view entry) {
    const std::string_view name = entry.substr(0, entry.find('=') + 1);
    for (const std::string& v : environment)
      if (std::string_view(v).substr(0, v.find('=') + 1) == name) return true;
    return false;
  };
  for (char** e = environ; *e != nullptr; ++e)
    if (!replaced(*e)) variables.emplace_back(*e);
  return variables;
}

// In the child just forked from `parent`: the program `args` in `dir`, its output into
// `out`; exit code 127 when it cannot be started.
[[noreturn]] void exec_child(pid_t parent, const std::filesystem::path& dir, int out, std::vector<char*>& args,
                             std::vector<char*>& envp) {
  die_with_parent(parent);
  // The program gets the signals this process leaves to its interrupt thread (interrupt.hpp).
  sigset_t all;
  sigfillset(&all);
  sigprocmask(SIG_UNBLOCK, &all, nullptr);
  if (chdir(dir.c_str()) != 0) _exit(127);
  dup2(out, STDOUT_FILENO);  // dup2 clears close-on-exec on the copies
  dup2(out, STDERR_FILENO);
  execvpe(args[0], args.data(), envp.data());
  _exit(127);
}

}  // namespace

int run_child(const std::vector<std::string>& argv, const std::filesystem::path& dir,
              const std::filesystem::path& log, const Deadline& deadline, const std::string& what,
              const std::vector<std::string>& environment, const LogWatcher& watch, const ChildBudget& budget) {
  deadline.check("before " + what + " started");
  std::vector<std::string> variables = child_environment(environment);
  std::vector<char*> envp;
  for (std::string& v : variables) envp.push_back(v.data());
  envp.push_back(nullptr);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  // The log is made here, so that it can be followed from its first byte.
  const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (out < 0) throw IoError(log.string() + ": cannot write the log of " + what);
  const int in = open(log.c_str(), O_RDONLY | O_CLOEXEC);
  std::fflush(nullptr);
  const pid_t parent = getpid();
  // mpirun is stopped with SIGTERM first, so that it takes the solver's ranks with it.
  const bool graceful = argv.front() == "mpirun";
  const RegisteredChild child(graceful);
  const pid_t pid = child.pid();
  if (pid < 0) {
    close(out);
    if (in >= 0) close(in);
    throw IoError(what + ": cannot start it (fork failed)");
  }
  if (pid == 0) exec_child(parent, dir, out, args, envp);
  close(out);
  // Everything the child has written since the last look, to the watcher; whether it wrote.
  std::string chunk(1 << 16, '\0');
  bool wrote = false;
  auto follow = [&] {
    bool stop = false;
    ssize_t n;
    while (in >= 0 && (n = read(in, chunk.data(), chunk.size())) > 0) {
      wrote = true;
      if (watch) stop = watch(std::string_view(chunk.data(), static_cast<std::size_t>(n))) || stop;
    }
    return stop;
  };
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  auto last_output = started;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  int status = 0;
  // Polled, so the deadline is noticed within a tenth of a second.
  while (true) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0) {
      if (in >= 0) close(in);
      throw IoError(what + ": lost track of it (waitpid failed)");
    }
    if (deadline.passed()) {
      stop_child(pid, graceful);
      if (in >= 0) close(in);
      deadline.check("while " + what + " ran (it was stopped)");
    }
    wrote = false;
    if (follow()) {  // the watcher says stop
      status = stop_child(pid, graceful);
      break;
    }
    if (wrote) last_output = Clock::now();
    if (seconds_since(started) > budget.seconds || seconds_since(last_output) > budget.idle_seconds) {
      stop_child(pid, graceful);
      if (in >= 0) close(in);
      return kChildOverBudget;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  follow();  // what it wrote last
  if (in >= 0) close(in);
  wait_if_interrupted();  // the interrupt killed it: its caller must not act on the failure (try again, keep files)
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace grainmesh
