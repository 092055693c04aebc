#include "common/allocator.hpp"

#include <malloc.h>

namespace grainmesh {

void keep_freed_memory() {
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMmapThreshold));
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(kTrimThreshold));
}

std::string malloc_tunables() {
  return "glibc.malloc.mmap_threshold=" + std::to_string(kMmapThreshold) +
         ":glibc.malloc.trim_threshold=" + std::to_string(kTrimThreshold);
}

}  // namespace grainmesh
