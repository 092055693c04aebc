// grainmesh's Python module, its native part (_grainmesh; the package python/grainmesh
// wraps it): a grainmesh command run as the program runs it — the program itself, started
// as a child of the interpreter — so the same checks, errors and outputs to the bit, and
// Ctrl-C stops it as it stops the program (its children stopped, nothing left behind). The
// interpreter, its GIL released, waits, relays what the command prints, and raises what
// Python's signal handlers raise once the child has cleaned up. Not linked with the
// libraries: a command run inside the interpreter would share its threads and locks (fork
// without exec is unsafe there), could take it down with a crash or the out-of-memory
// killer, and would need every library built position-independent.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "pipelines/default_config.hpp"

extern char** environ;

namespace py = pybind11;
using namespace grainmesh;

namespace {

// A pipe whose ends close with it.
struct Pipe {
  std::array<int, 2> fd{-1, -1};
  Pipe() {
    if (pipe2(fd.data(), O_CLOEXEC) != 0) throw std::runtime_error("grainmesh: cannot make a pipe");
  }
  ~Pipe() { close_all(); }
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  void close_end(int k) {
    if (fd[k] >= 0) close(fd[k]);
    fd[k] = -1;
  }
  void close_all() {
    close_end(0);
    close_end(1);
  }
};

// Starts `binary ARGS...` with its stdout and stderr on the pipes, the interrupt signals
// and SIGPIPE at their defaults (Python ignores SIGPIPE) and none blocked.
pid_t start(const std::string& binary, const std::vector<std::string>& args, Pipe& out, Pipe& err) {
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_adddup2(&files, out.fd[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&files, err.fd[1], STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) sigaddset(&defaults, s);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  std::vector<char*> argv{const_cast<char*>(binary.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int failed = posix_spawn(&pid, binary.c_str(), &files, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attributes);
  if (failed != 0)
    throw std::runtime_error("grainmesh: cannot start " + binary + ": " + std::strerror(failed));
  return pid;
}

// Reads what is there on `fd` into `text`; false at its end.
bool drain(int fd, std::string& text) {
  char buffer[65536];
  for (;;) {
    const ssize_t got = read(fd, buffer, sizeof buffer);
    if (got > 0) {
      text.append(buffer, static_cast<std::size_t>(got));
      continue;
    }
    if (got < 0 && errno == EINTR) continue;
    return got < 0 && errno == EAGAIN;
  }
}

// Writes the whole lines of `text` to Python's sys.`stream` (the notebook's, where there is
// one), all of it when `all`, and keeps the rest. The command's error line is left out: it
// is the exception's message.
void relay(const char* stream, std::string& text, bool all) {
  const std::size_t end = all ? text.size() : text.rfind('\n') + 1;  // npos + 1 = 0: no whole line
  std::string lines;
  for (std::size_t at = 0; at < end;) {
    const std::size_t newline = text.find('\n', at);
    const std::size_t next = newline < end ? newline + 1 : end;
    if (text.compare(at, kErrorPrefix.size(), kErrorPrefix) != 0) lines.append(text, at, next - at);
    at = next;
  }
  text.erase(0, end);
  if (lines.empty()) return;
  py::module_::import("sys").attr(stream).attr("write")(lines);
  py::module_::import("sys").attr(stream).attr("flush")();
}

// Runs `binary ARGS...` (the grainmesh program) in a child process; returns its exit code
// (128 + the signal that ended it) and everything it wrote to stderr. What it prints is
// relayed to sys.stdout and sys.stderr unless `quiet`. On Ctrl-C (or any signal Python
// raises on) the child is sent SIGINT, waited for (it removes what it had begun), and the
// Python exception raised.
py::tuple command(const std::string& binary, const std::vector<std::string>& args, bool quiet) {
  Pipe out, err;
  const pid_t pid = start(binary, args, out, err);
  out.close_end(1);
  err.close_end(1);
  for (int fd : {out.fd[0], err.fd[0]}) fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
  std::string printed, errors, all_errors;
  bool out_open = true, err_open = true;
  std::optional<py::error_already_set> raised;
  int status = 0;
  // Until the child has ended and its output is read (or, should a child of its own keep
  // the pipes open after it, for a second after it ended).
  auto ended_at = std::chrono::steady_clock::time_point::max();
  for (bool running = true; running || ((out_open || err_open) &&
                                        std::chrono::steady_clock::now() - ended_at < std::chrono::seconds(1));) {
    {
      py::gil_scoped_release unlocked;
      std::array<pollfd, 2> fds{{{out_open ? out.fd[0] : -1, POLLIN, 0}, {err_open ? err.fd[0] : -1, POLLIN, 0}}};
      poll(fds.data(), fds.size(), 100);  // with neither open: a tenth of a second's wait
      if (out_open) out_open = drain(out.fd[0], printed);
      if (err_open) {
        const std::size_t before = errors.size();
        err_open = drain(err.fd[0], errors);
        all_errors.append(errors, before, std::string::npos);
      }
      if (running && waitpid(pid, &status, WNOHANG) == pid) {
        running = false;
        ended_at = std::chrono::steady_clock::now();
      }
    }
    if (quiet) {
      printed.clear();
      errors.clear();
    } else {
      const bool ended = !running && !out_open && !err_open;
      relay("stdout", printed, ended);
      relay("stderr", errors, ended);
    }
    if (!raised && PyErr_CheckSignals() != 0) {
      raised.emplace();  // taken out of Python's state (raised again below) while the child cleans up
      if (running) kill(pid, SIGINT);
    }
  }
  if (!quiet) {  // what is left of a last line
    relay("stdout", printed, true);
    relay("stderr", errors, true);
  }
  if (raised) throw *raised;
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  return py::make_tuple(code, all_errors);
}

}  // namespace

PYBIND11_MODULE(_grainmesh, m) {
  m.doc() = "grainmesh's native part: commands run as the grainmesh program runs them";
  m.def("command", &command, py::arg("binary"), py::arg("args"), py::arg("quiet") = false,
        "Runs `binary ARGS...` (the grainmesh program); returns (exit code, stderr). Ctrl-C stops it, then "
        "KeyboardInterrupt is raised.");
  m.attr("default_config") = py::str(kDefaultRunConfig);
  m.attr("error_prefix") = py::str(std::string(kErrorPrefix));
  py::dict codes;
  codes["config"] = static_cast<int>(kExitConfig);
  codes["geometry"] = static_cast<int>(kExitGeometry);
  codes["io"] = static_cast<int>(kExitIo);
  codes["time_limit"] = static_cast<int>(kExitTimeLimit);
  codes["solve"] = static_cast<int>(kExitSolve);
  m.attr("exit_codes") = codes;
}
