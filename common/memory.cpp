#include "common/memory.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
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

}  // namespace

double tree_resident_mib(int pid) {
  // Every process's parent and resident pages, from /proc/PID/stat (after the name's
  // closing parenthesis: state, ppid, ... with rss the 22nd field).
  std::multimap<int, int> children;
  std::map<int, long> pages;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", std::filesystem::directory_options::skip_permission_denied)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(entry.path() / "stat");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto close = text.rfind(')');
    if (close == std::string::npos) continue;  // gone meanwhile
    std::istringstream fields(text.substr(close + 2));
    std::vector<std::string> f;
    for (std::string s; fields >> s && f.size() < 22;) f.push_back(s);
    if (f.size() < 22) continue;
    const int id = std::stoi(name);
    children.emplace(std::stoi(f[1]), id);
    pages[id] = std::stol(f[21]);
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
        const double now = tree_resident_mib(static_cast<int>(getpid()));
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
  if (with_children) sampler_ = std::make_unique<Sampler>();
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
