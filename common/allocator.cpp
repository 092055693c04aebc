#include "common/allocator.hpp"

#include <malloc.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

namespace grainmesh {

void keep_freed_memory() {
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMmapThreshold));
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(kTrimThreshold));
}

std::string malloc_tunables() {
  return "glibc.malloc.mmap_threshold=" + std::to_string(kMmapThreshold) +
         ":glibc.malloc.trim_threshold=" + std::to_string(kTrimThreshold);
}

void ask_for_huge_pages(char** argv) {
  constexpr const char* kTunable = "glibc.malloc.hugetlb";
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string before = tunables ? tunables : "";
  if (before.find(kTunable) != std::string::npos) return;  // asked already, or told otherwise
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  const std::string modes{std::istreambuf_iterator<char>(mode), std::istreambuf_iterator<char>()};
  if (modes.find("[madvise]") == std::string::npos) return;  // "always" needs no asking; "never" gives none
  const std::string after = (before.empty() ? "" : before + ":") + kTunable + "=1";
  if (setenv("GLIBC_TUNABLES", after.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Still here: the exec failed, run as we are (the tunable set now changes nothing).
  if (tunables) setenv("GLIBC_TUNABLES", before.c_str(), 1); else unsetenv("GLIBC_TUNABLES");
}

}  // namespace grainmesh
