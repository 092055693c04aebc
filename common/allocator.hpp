// glibc's allocator told to keep the memory it frees. By default it maps every block above
// a threshold from the kernel and unmaps it when freed, and returns the top of the heap
// once it holds more than a threshold free: a program that allocates and frees whole
// fields again and again (the mesher, the solver every correction) then spends much of its
// time in page faults. Here both thresholds are far above any field's size.
#pragma once

#include <cstddef>
#include <string>

namespace grainmesh {

inline constexpr std::size_t kMmapThreshold = std::size_t{256} << 20;  // 256 MiB
inline constexpr std::size_t kTrimThreshold = std::size_t{1} << 30;    // 1 GiB

// For this process (mallopt), first thing in main.
void keep_freed_memory();

// The same for a child process, as GLIBC_TUNABLES entries (glibc.malloc.mmap_threshold=...:...).
std::string malloc_tunables();

}  // namespace grainmesh
