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

// glibc's allocator told to ask the kernel for transparent huge pages
// (glibc.malloc.hugetlb=1, a tunable only the environment sets, before the process starts):
// where the kernel gives them on request (transparent_hugepage "madvise"), and
// GLIBC_TUNABLES does not say otherwise, the process execs itself once more with it, first
// thing in main. A first touch then maps 2 MiB rather than 4 KiB: the 1,000-grain cell's
// finite elements 3.96 -> 3.37 s (median of five), the 3D example's run 19.8 -> 18.4 s.
// Nothing happens where the exec fails.
void ask_for_huge_pages(char** argv);

}  // namespace grainmesh
