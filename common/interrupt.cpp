#include "common/interrupt.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

// Holds every other thread of the process still while an interrupt removes what they were
// writing: a thread still running could write a file into a staging directory just removed,
// or make it anew (create_directories). Threads take it at once, in any code; they hold what
// locks they held (malloc's among them), so the interrupt uses only system calls after it.
int freeze_signal() { return SIGRTMIN + 3; }
std::atomic<int> g_frozen{0};
void hold_still(int) {
  g_frozen.fetch_add(1);
  for (;;) pause();
}

// The thread ids of this process (up to `capacity`), read with system calls only.
int thread_ids(pid_t* ids, int capacity) {
  const int fd = open("/proc/self/task", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return 0;
  int n = 0;
  alignas(dirent64) char buffer[4096];
  for (ssize_t got; (got = getdents64(fd, buffer, sizeof buffer)) > 0;)
    for (ssize_t at = 0; at < got;) {
      const auto* e = reinterpret_cast<const dirent64*>(buffer + at);
      at += e->d_reclen;
      const long id = std::strtol(e->d_name, nullptr, 10);
      if (id > 0 && n < capacity) ids[n++] = static_cast<pid_t>(id);
    }
  close(fd);
  return n;
}

// Sends every thread but this one the freeze signal, again for threads started meanwhile,
// and waits (up to half a second) until they all hold still.
void freeze_other_threads() {
  constexpr int kCapacity = 1024;
  pid_t sent[kCapacity];
  int count = 0;
  for (bool more = true; more;) {
    more = false;
    pid_t ids[kCapacity];
    const int n = thread_ids(ids, kCapacity);
    for (int i = 0; i < n; ++i) {
      if (ids[i] == gettid() || std::find(sent, sent + count, ids[i]) != sent + count || count == kCapacity) continue;
      if (tgkill(getpid(), ids[i], freeze_signal()) == 0) {
        sent[count++] = ids[i];
        more = true;
      }
    }
  }
  const auto until = Clock::now() + std::chrono::milliseconds(500);
  while (g_frozen.load() < count && Clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

// Removes `name` (under directory `at`): a file, or a directory with all it holds; system
// calls only (freeze_other_threads).
void remove_tree(int at, const char* name, int depth = 0) {
  if (unlinkat(at, name, 0) == 0 || errno == ENOENT || depth > 64) return;
  const int fd = openat(at, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  alignas(dirent64) char buffer[4096];
  for (int pass = 0; pass < 3; ++pass) {  // entries removed while listing may hide others: list again
    lseek(fd, 0, SEEK_SET);
    for (ssize_t got; (got = getdents64(fd, buffer, sizeof buffer)) > 0;)
      for (ssize_t i = 0; i < got;) {
        const auto* e = reinterpret_cast<const dirent64*>(buffer + i);
        i += e->d_reclen;
        if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0) remove_tree(fd, e->d_name, depth + 1);
      }
    if (unlinkat(at, name, AT_REMOVEDIR) == 0 || errno != ENOTEMPTY) break;
  }
  close(fd);
}

[[noreturn]] void handle(int signal, Registry& r) {
  g_interrupted = true;
  const std::lock_guard<std::mutex> lock(r.mutex);  // held until the end: nothing registers or forks after this
  std::vector<pid_t> graceful, hard;
  for (const auto& [id, c] : r.children) {
    (c.graceful ? graceful : hard).push_back(c.pid);
    kill(c.pid, c.graceful ? SIGTERM : SIGKILL);
  }
  if (!all_ended(graceful, 10.0))
    for (const pid_t pid : graceful) kill(pid, SIGKILL);
  all_ended(graceful, 1.0);
  all_ended(hard, 1.0);
  std::vector<const char*> paths;
  for (const auto& [id, path] : r.paths) paths.push_back(path.c_str());
  const std::string line = std::string(isatty(STDERR_FILENO) ? "\r\033[K" : "") + "grainmesh: interrupted; " + r.message + "\n";
  freeze_other_threads();  // from here on system calls only
  for (const char* path : paths) remove_tree(AT_FDCWD, path);
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

void install_interrupt_handling(std::string message) {
  const sigset_t set = interrupt_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  struct sigaction freeze {};
  freeze.sa_handler = hold_still;
  sigemptyset(&freeze.sa_mask);
  sigaction(freeze_signal(), &freeze, nullptr);
  auto* r = new Registry;  // lives as long as the process (the handling thread uses it until exit)
  r->message = std::move(message);
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

RegisteredChild::RegisteredChild(bool graceful) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);  // an interrupt waits until the child is registered
  pid_ = fork();
  if (pid_ <= 0) return;  // failed, or the child (where its copy of the lock is released on return)
  id_ = r.next++;
  r.children[id_] = {pid_, graceful};
}

RegisteredChild::~RegisteredChild() {
  if (id_ < 0) return;
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
