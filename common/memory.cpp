#include "common/memory.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace grainmesh {
namespace {

constexpr double kKiBPerMiB = 1024.0;

// VmHWM of this process in MiB (the kernel's high-water mark of its resident set).
double own_peak_mib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / kKiBPerMiB;
  return 0.0;
}

// The high-water mark back to what is resident now (Linux 4.0 on); where that is not
// allowed the stage's peak is the process's peak so far.
void reset_own_peak() { std::ofstream("/proc/self/clear_refs") << "5"; }

// The first number in `file` (bytes, or kB after `key` in /proc/meminfo); negative when
// it holds none ("max", absent).
double number_in(const std::filesystem::path& file, const std::string& key = {}) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (!key.empty() && line.rfind(key, 0) != 0) continue;
    try {
      return std::stod(key.empty() ? line : line.substr(key.size()));
    } catch (const std::exception&) {
      return -1.0;
    }
  }
  return -1.0;
}

}  // namespace

double available_memory_mib() {
  double mib = std::numeric_limits<double>::infinity();
  if (const double kib = number_in("/proc/meminfo", "MemAvailable:"); kib >= 0.0) mib = kib / kKiBPerMiB;
  // This process's control group, v2 ("0::PATH") or v1's memory controller ("N:memory:PATH").
  std::ifstream groups("/proc/self/cgroup");
  for (std::string line; std::getline(groups, line);) {
    const auto second = line.find(':', line.find(':') + 1);
    if (second == std::string::npos) continue;
    const std::string controllers = line.substr(line.find(':') + 1, second - line.find(':') - 1);
    const std::string path = line.substr(second + 1);
    std::filesystem::path dir;
    std::string limit, usage;
    if (controllers.empty()) {
      dir = "/sys/fs/cgroup" + path, limit = "memory.max", usage = "memory.current";
    } else if (controllers == "memory") {
      dir = "/sys/fs/cgroup/memory" + path, limit = "memory.limit_in_bytes", usage = "memory.usage_in_bytes";
    } else {
      continue;
    }
    const double max = number_in(dir / limit), used = number_in(dir / usage);
    if (max >= 0.0 && used >= 0.0) mib = std::min(mib, std::max(0.0, max - used) / (kKiBPerMiB * kKiBPerMiB));
  }
  // The process's address-space limit (ulimit -v; RLIMIT_AS) less what it has mapped.
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
    if (const double kib = number_in("/proc/self/status", "VmSize:"); kib >= 0.0)
      mib = std::min(mib, std::max(0.0, static_cast<double>(as.rlim_cur) / kKiBPerMiB - kib) / kKiBPerMiB);
  return mib;
}

double tree_resident_mib(int pid) {
  // Every process's parent and resident pages, from /proc/PID/stat (after the name's
  // closing parenthesis: state, ppid, ... with rss the 22nd field).
  // Processes come and go while /proc is read: one gone is skipped, and an error ends
  // the reading with what was read (never an exception: this runs on a sampling thread).
  std::multimap<int, int> children;
  std::map<int, long> pages;
  std::error_code error;
  for (std::filesystem::directory_iterator it("/proc", error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    // read(2), not a stream: a process that ends while it is read fails the read (ESRCH),
    // which a stream would throw.
    const int fd = open((it->path() / "stat").c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) continue;
    char buf[1024];
    const ssize_t n = read(fd, buf, sizeof buf - 1);
    close(fd);
    if (n <= 0) continue;
    const std::string text(buf, static_cast<std::size_t>(n));
    const auto close = text.rfind(')');
    if (close == std::string::npos) continue;  // gone meanwhile
    std::istringstream fields(text.substr(close + 1));
    std::vector<long> f;  // from the state on; the state itself reads as 0
    for (std::string field; fields >> field && f.size() < 22;) f.push_back(std::strtol(field.c_str(), nullptr, 10));
    if (f.size() < 22) continue;
    const int id = static_cast<int>(std::strtol(name.c_str(), nullptr, 10));
    children.emplace(static_cast<int>(f[1]), id);
    pages[id] = f[21];
  }
  long total = 0;
  std::vector<int> stack{pid};
  while (!stack.empty()) {
    const int p = stack.back();
    stack.pop_back();
    if (const auto it = pages.find(p); it != pages.end()) total += it->second;
    for (auto [it, end] = children.equal_range(p); it != end; ++it) stack.push_back(it->second);
  }
  return static_cast<double>(total) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (kKiBPerMiB * kKiBPerMiB);
}

struct StageMemory::Sampler {
  std::mutex mutex;
  std::condition_variable wake;
  bool stop = false;
  double peak = 0.0;
  std::thread thread;

  Sampler() {
    thread = std::thread([this] {
      std::unique_lock lock(mutex);
      while (!stop) {
        lock.unlock();
        double now = 0.0;
        try {
          now = tree_resident_mib(static_cast<int>(getpid()));
        } catch (...) {
          // A sample lost (no memory to read /proc with): the others stand.
        }
        lock.lock();
        peak = std::max(peak, now);
        wake.wait_for(lock, std::chrono::milliseconds(100), [this] { return stop; });
      }
    });
  }
  double finish() {
    {
      std::lock_guard lock(mutex);
      stop = true;
    }
    wake.notify_one();
    thread.join();
    return peak;
  }
};

StageMemory::StageMemory(bool with_children) {
  reset_own_peak();
  if (!with_children) return;
  try {
    sampler_ = std::make_unique<Sampler>();
  } catch (const std::system_error&) {
    // No thread to be had: the stage's figure is this process's alone.
  }
}

StageMemory::~StageMemory() {
  if (sampler_) peak_mib();
}

double StageMemory::peak_mib() {
  if (peak_ >= 0.0) return peak_;
  peak_ = own_peak_mib();
  if (sampler_) {
    peak_ = std::max(peak_, sampler_->finish());
    sampler_.reset();
  }
  return peak_;
}

}  // namespace grainmesh
