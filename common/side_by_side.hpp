// Independent jobs run side by side on a few threads: the load cases of a homogenisation,
// each an external solver process.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace grainmesh {

// The machine's cores, at least one.
inline int cores() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

// Runs job(k) for every k of `order` (a permutation of 0 .. n-1, the order they start in),
// up to `parallel` at a time, each thread taking the next as it finishes one. When jobs
// throw, all are still run, then the lowest k's exception is rethrown.
template <class Job>
void side_by_side(const std::vector<int>& order, int parallel, Job job) {
  const int n = static_cast<int>(order.size());
  std::vector<std::exception_ptr> failed(order.size());
  std::atomic<int> next{0};
  auto work = [&] {
    for (int i = next++; i < n; i = next++) {
      const int k = order[static_cast<std::size_t>(i)];
      try {
        job(k);
      } catch (...) {
        failed[static_cast<std::size_t>(k)] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> running;
  for (int w = 0; w < std::clamp(parallel, 1, std::max(n, 1)); ++w) running.emplace_back(work);
  for (std::thread& t : running) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace grainmesh
