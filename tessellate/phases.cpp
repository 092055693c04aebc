// Phase labels: which grains make up each phase's area fraction.
#include "tessellate/phases.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <tuple>

namespace grainmesh {

namespace {

// The order in which grains are offered to a phase.
std::vector<int> arrangement_order(const std::vector<int>& free, const std::vector<std::vector<int>>& neighbours,
                                   const std::vector<int>& label, Arrangement arrangement,
                                   const std::vector<double>& rank) {
  std::vector<int> order = free;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return rank[a] < rank[b]; });
  if (arrangement == Arrangement::random) return order;
  std::vector<char> is_free(label.size(), 0);
  for (int g : free) is_free[g] = 1;
  std::vector<char> taken(label.size(), 0);
  if (arrangement == Arrangement::dispersed) {
    // First every grain with no neighbour taken yet, then the others.
    std::vector<int> first, second;
    for (int g : order) {
      bool alone = true;
      for (int n : neighbours[g]) alone = alone && !taken[n];
      (alone ? first : second).push_back(g);
      if (alone) taken[g] = 1;
    }
    first.insert(first.end(), second.begin(), second.end());
    return first;
  }
  // Clustered: grow from the first grain, always taking the free grain with the most
  // neighbours already taken; restart from the next unreached grain when cut off.
  std::vector<int> out;
  std::vector<int> count(label.size(), 0);
  using Item = std::tuple<int, double, int>;  // (-taken neighbours, rank, grain)
  std::priority_queue<Item, std::vector<Item>, std::greater<>> heap;
  std::size_t next_start = 0;
  while (out.size() < order.size()) {
    if (heap.empty()) {
      while (taken[order[next_start]]) ++next_start;
      heap.emplace(0, rank[order[next_start]], order[next_start]);
    }
    const auto [neg, r, g] = heap.top();
    heap.pop();
    if (taken[g] || -neg != count[g]) continue;
    taken[g] = 1;
    out.push_back(g);
    for (int n : neighbours[g])
      if (is_free[n] && !taken[n]) {
        ++count[n];
        heap.emplace(-count[n], rank[n], n);
      }
  }
  return out;
}

// One phase's grains as they are picked: the phase, its target area, the grains chosen
// and their area.
struct PhasePick {
  int phase = -1;
  double target = 0.0;
  double sum = 0.0;
  std::vector<int> chosen;
};

// Offers the free grains in the arrangement's order, taking each that brings the sum
// closer to the target, until it is reached.
PhasePick pick_in_order(const std::vector<double>& areas, const std::vector<int>& order, int phase, double target,
                        std::vector<int>& label) {
  PhasePick pick{.phase = phase, .target = target, .sum = 0.0, .chosen = {}};
  for (int g : order) {
    if (pick.sum >= target) break;
    if (std::abs(pick.sum + areas[g] - target) < std::abs(pick.sum - target)) {
      pick.sum += areas[g];
      label[g] = phase;
      pick.chosen.push_back(g);
    }
  }
  return pick;
}

// Best single swaps, at most eight: a chosen grain out, a free one of the right size in,
// while that brings the sum closer to the target. A swap keeps the arrangement:
// clustered grains join next to the phase, dispersed ones away from it.
void swap_towards_target(const std::vector<double>& areas, const std::vector<std::vector<int>>& neighbours,
                         Arrangement arrangement, const std::vector<int>& free, std::vector<int>& label,
                         PhasePick& pick) {
  const int p = pick.phase;
  const double target = pick.target;
  double& sum = pick.sum;
  for (int round = 0; round < 8; ++round) {
    std::vector<std::pair<double, int>> pool;
    for (int g : free)
      if (label[g] < 0) pool.emplace_back(areas[g], g);
    std::sort(pool.begin(), pool.end());
    double best_gain = 0.0;
    int best_out = -1, best_in = -1;
    auto consider = [&](int out, int in) {
      const double gain = std::abs(sum - target) - std::abs(sum - (out >= 0 ? areas[out] : 0.0) + areas[in] - target);
      if (gain > best_gain) {
        best_gain = gain;
        best_out = out;
        best_in = in;
      }
    };
    auto fits = [&](int in, int out) {
      if (arrangement == Arrangement::random) return true;
      bool touches = false;
      for (int n : neighbours[in]) touches = touches || (n != out && label[n] == p);
      return arrangement == Arrangement::clustered ? touches : !touches;
    };
    constexpr int kScan = 64;  // pool entries looked at on either side of the ideal size
    for (int out : pick.chosen) {
      if (label[out] != p) continue;
      const double want = areas[out] + (target - sum);
      const auto at = std::lower_bound(pool.begin(), pool.end(), std::make_pair(want, -1)) - pool.begin();
      for (auto k = at; k < static_cast<std::ptrdiff_t>(pool.size()) && k < at + kScan; ++k)
        if (fits(pool[k].second, out)) {
          consider(out, pool[k].second);
          break;
        }
      for (auto k = at - 1; k >= 0 && k >= at - kScan; --k)
        if (fits(pool[k].second, out)) {
          consider(out, pool[k].second);
          break;
        }
    }
    if (best_out < 0) break;
    label[best_out] = -1;
    label[best_in] = p;
    sum += areas[best_in] - areas[best_out];
    std::replace(pick.chosen.begin(), pick.chosen.end(), best_out, best_in);
  }
}

}  // namespace

std::vector<int> assign_phases(const std::vector<double>& areas, const std::vector<std::vector<int>>& neighbours,
                               const std::vector<Phase>& all, const std::vector<int>& phases, double total_area,
                               Arrangement arrangement, Rng& rng) {
  const int n = static_cast<int>(areas.size());
  std::vector<double> rank(n);
  for (double& r : rank) r = uniform01(rng);
  int rest = -1;
  std::vector<int> explicit_phases;
  for (int p : phases) {
    if (all[p].rest) rest = p;
    else explicit_phases.push_back(p);
  }
  if (rest < 0) {  // the last phase takes what rounding leaves
    rest = explicit_phases.back();
    explicit_phases.pop_back();
  }
  std::vector<int> label(n, -1);
  for (int p : explicit_phases) {
    std::vector<int> free;
    for (int g = 0; g < n; ++g)
      if (label[g] < 0) free.push_back(g);
    PhasePick pick = pick_in_order(areas, arrangement_order(free, neighbours, label, arrangement, rank), p,
                                   all[p].fraction * total_area, label);
    swap_towards_target(areas, neighbours, arrangement, free, label, pick);
  }
  for (int& l : label)
    if (l < 0) l = rest;
  return label;
}

double target_fraction(const std::vector<Phase>& phases, int p) {
  if (!phases[p].rest) return phases[p].fraction;
  double sum = 0.0;
  for (const Phase& q : phases) sum += q.rest ? 0.0 : q.fraction;
  return 1.0 - sum;
}

}  // namespace grainmesh
