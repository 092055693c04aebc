#include "common/interrupt.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

namespace grainmesh {

namespace {

struct Child {
  pid_t pid;
  bool graceful;
};

// What an interrupt must undo. Allocated anew by each install (a forked child's copy of
// its parent's, whose mutex another thread may have held at the fork, is left alone).
struct Registry {
  std::mutex mutex;
  std::map<int, std::filesystem::path> paths;
  std::map<int, Child> children;
  int next = 0;
  std::string message = "nothing was written";
};

std::atomic<Registry*> g_registry{nullptr};
std::atomic<bool> g_interrupted{false};

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGHUP);
  return set;
}

using Clock = std::chrono::steady_clock;

// Whether child `pid` has ended (and is reaped, by us or by the thread that waits for it).
bool ended(pid_t pid) {
  int status = 0;
  const pid_t r = waitpid(pid, &status, WNOHANG);
  return r == pid || (r < 0 && kill(pid, 0) != 0);
}

// Waits up to `seconds` for every child in `children` to end; true when they all did.
bool all_ended(const std::vector<pid_t>& children, double seconds) {
  const auto until = Clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    bool all = true;
    for (const pid_t pid : children) all = ended(pid) && all;
    if (all) return true;
    if (Clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

[[noreturn]] void handle(int signal, Registry& r) {
  g_interrupted = true;
  const std::lock_guard<std::mutex> lock(r.mutex);  // held until the end: nothing registers after this
  std::vector<pid_t> graceful, hard;
  for (const auto& [id, c] : r.children) {
    (c.graceful ? graceful : hard).push_back(c.pid);
    kill(c.pid, c.graceful ? SIGTERM : SIGKILL);
  }
  if (!all_ended(graceful, 10.0))
    for (const pid_t pid : graceful) kill(pid, SIGKILL);
  all_ended(graceful, 1.0);
  all_ended(hard, 1.0);
  for (const auto& [id, path] : r.paths) {
    std::error_code ec;
    for (int attempt = 0; attempt < 3; ++attempt) {  // a child killed a moment ago may have left a file appearing
      std::filesystem::remove_all(path, ec);
      if (!std::filesystem::exists(path, ec)) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  const std::string line = std::string(isatty(STDERR_FILENO) ? "\r\033[K" : "") + "grainmesh: interrupted; " + r.message + "\n";
  [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, line.data(), line.size());
  _exit(128 + signal);
}

void wait_for_signals(Registry* r) {
  const sigset_t set = interrupt_signals();
  int signal = 0;
  while (sigwait(&set, &signal) != 0) {
  }
  handle(signal, *r);
}

Registry& registry() {
  Registry* r = g_registry.load();
  if (r == nullptr) {  // a library user who never installed the handling: registrations are kept, never acted on
    static Registry fallback;
    return fallback;
  }
  return *r;
}

}  // namespace

void install_interrupt_handling() {
  const sigset_t set = interrupt_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  auto* r = new Registry;  // lives as long as the process (the handling thread uses it until exit)
  g_registry = r;
  g_interrupted = false;
  std::thread(wait_for_signals, r).detach();
}

void set_interrupt_message(std::string message) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  r.message = std::move(message);
}

bool interrupted() { return g_interrupted; }

void wait_if_interrupted() {
  while (g_interrupted) std::this_thread::sleep_for(std::chrono::seconds(1));
}

TemporaryPath::TemporaryPath(std::filesystem::path path) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  id_ = r.next++;
  r.paths[id_] = std::move(path);
}

TemporaryPath::~TemporaryPath() { release(); }

TemporaryPath::TemporaryPath(TemporaryPath&& other) noexcept : id_(other.id_) { other.id_ = -1; }

TemporaryPath& TemporaryPath::operator=(TemporaryPath&& other) noexcept {
  if (this != &other) {
    release();
    id_ = other.id_;
    other.id_ = -1;
  }
  return *this;
}

void TemporaryPath::release() {
  if (id_ < 0) return;
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  r.paths.erase(id_);
  id_ = -1;
}

ChildRegistration::ChildRegistration(pid_t pid, bool graceful) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  id_ = r.next++;
  r.children[id_] = {pid, graceful};
}

ChildRegistration::~ChildRegistration() {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  r.children.erase(id_);
}

int stop_child(pid_t pid, bool graceful, double grace_seconds) {
  int status = 0;
  if (graceful) {
    kill(pid, SIGTERM);
    const auto until = Clock::now() + std::chrono::duration<double>(grace_seconds);
    while (Clock::now() < until) {
      const pid_t r = waitpid(pid, &status, WNOHANG);
      if (r == pid || r < 0) return status;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return status;
}

}  // namespace grainmesh
