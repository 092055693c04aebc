// Phase labels rearranged toward a contiguity: like-sized grains of the phase and of the
// others trade labels, the best trade for each grain in turn.
#include "tessellate/contiguity.hpp"

#include <algorithm>
#include <cmath>

namespace grainmesh {

namespace {

// The lengths the phase shares with itself (own) and with the others (other), and each
// grain's boundary with the phase (with) and with the rest (without); a label flip
// updates them from the flipped grain's neighbours alone.
struct Boundary {
  const SharedBoundaries& shared;
  int phase;
  std::vector<int>& label;
  double own = 0.0, other = 0.0;
  std::vector<double> with, without;

  Boundary(const SharedBoundaries& s, int p, std::vector<int>& l)
      : shared(s), phase(p), label(l), with(l.size(), 0.0), without(l.size(), 0.0) {
    for (std::size_t g = 0; g < l.size(); ++g)
      for (const auto& [m, length] : s[g]) {
        (label[static_cast<std::size_t>(m)] == phase ? with : without)[g] += length;
        if (static_cast<int>(g) < m && (label[g] == phase) != (label[static_cast<std::size_t>(m)] == phase)) other += length;
        if (static_cast<int>(g) < m && label[g] == phase && label[static_cast<std::size_t>(m)] == phase) own += length;
      }
  }
  double contiguity(double own_, double other_) const {
    // The sums are kept up by additions and removals: a rounding's worth is none.
    if (own_ <= 1e-12 * (own_ + other_)) own_ = 0.0;
    return own_ + other_ > 0.0 ? 2.0 * own_ / (2.0 * own_ + other_) : 0.0;
  }
  double contiguity() const { return contiguity(own, other); }
  // The contiguity after grain a leaves the phase and grain b joins it.
  double after_swap(int a, int b) const {
    double shared_ab = 0.0;
    for (const auto& [m, length] : shared[static_cast<std::size_t>(a)])
      if (m == b) shared_ab += length;
    const double own1 = own - with[a], other1 = other + with[a] - without[a];
    const double with_b = with[b] - shared_ab, without_b = without[b] + shared_ab;
    return contiguity(own1 + with_b, other1 + without_b - with_b);
  }
  void flip(int g, int to) {
    const bool joins = to == phase;
    if (joins) {
      own += with[g];
      other += without[g] - with[g];
    } else {
      own -= with[g];
      other += with[g] - without[g];
    }
    label[static_cast<std::size_t>(g)] = to;
    for (const auto& [m, length] : shared[static_cast<std::size_t>(g)]) {
      with[m] += joins ? length : -length;
      without[m] += joins ? -length : length;
    }
  }
};

}  // namespace

double labelled_contiguity(const std::vector<int>& label, const SharedBoundaries& shared, int phase) {
  std::vector<int> copy = label;
  return Boundary(shared, phase, copy).contiguity();
}

double arrange_contiguity(std::vector<int>& label, const std::vector<double>& areas, const SharedBoundaries& shared,
                          int phase, double target, double target_area, double slack, Rng& rng) {
  Boundary b(shared, phase, label);
  const int n = static_cast<int>(label.size());
  double sum = 0.0;
  for (int g = 0; g < n; ++g)
    if (label[g] == phase) sum += areas[g];
  const double allowed = std::max(std::abs(sum - target_area), slack);
  // The other phases' grains by area: a trade looks near the size that keeps the sum.
  std::vector<std::pair<double, int>> pool;
  for (int g = 0; g < n; ++g)
    if (label[g] != phase) pool.emplace_back(areas[g], g);
  std::sort(pool.begin(), pool.end());
  constexpr int kScan = 48;           // pool entries looked at on either side
  constexpr double kClose = 0.002;    // near enough: stop
  constexpr int kSweeps = 400;
  for (int sweep = 0; sweep < kSweeps && std::abs(b.contiguity() - target) > kClose; ++sweep) {
    std::vector<int> members;
    for (int g = 0; g < n; ++g)
      if (label[g] == phase) members.push_back(g);
    for (std::size_t k = members.size(); k > 1; --k)  // Fisher-Yates with our own draws
      std::swap(members[k - 1], members[static_cast<std::size_t>(uniform01(rng) * static_cast<double>(k))]);
    bool changed = false;
    for (const int a : members) {
      const double now = std::abs(b.contiguity() - target);
      if (now <= kClose) break;
      const double want = areas[a] + (target_area - sum);
      const auto at = std::lower_bound(pool.begin(), pool.end(), std::make_pair(want, -1)) - pool.begin();
      double best = now;
      std::ptrdiff_t best_k = -1;
      for (std::ptrdiff_t k = std::max<std::ptrdiff_t>(0, at - kScan);
           k < std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(pool.size()), at + kScan); ++k) {
        const int in = pool[k].second;
        if (std::abs(sum - areas[a] + areas[in] - target_area) > allowed) continue;
        const double next = std::abs(b.after_swap(a, in) - target);
        if (next < best - 1e-12) best = next, best_k = k;
      }
      if (best_k < 0) continue;
      const int in = pool[best_k].second;
      const int in_label = label[in];
      b.flip(a, in_label);
      b.flip(in, phase);
      sum += areas[in] - areas[a];
      pool.erase(pool.begin() + best_k);
      pool.insert(std::lower_bound(pool.begin(), pool.end(), std::make_pair(areas[a], a)), {areas[a], a});
      changed = true;
    }
    if (!changed) break;
  }
  return b.contiguity();
}

std::optional<std::pair<double, double>> reach_contiguity(std::vector<int>& label, const std::vector<double>& areas,
                                                          const SharedBoundaries& shared, int phase, double target,
                                                          double target_area, double slack, double tolerance, Rng& rng) {
  const std::vector<int> start = label;
  const double reached = arrange_contiguity(label, areas, shared, phase, target, target_area, slack, rng);
  if (std::abs(reached - target) <= tolerance) return std::nullopt;
  std::pair<double, double> range;
  for (double* end : {&range.first, &range.second}) {
    std::vector<int> trial = start;
    *end = arrange_contiguity(trial, areas, shared, phase, end == &range.first ? 0.0 : 1.0, target_area, slack, rng);
  }
  return range;
}

int contacts_nearest(int most, double target, const std::function<double(int)>& contiguity) {
  int lo = 0, hi = most;  // the fewest reaching the target lie in [lo, hi]
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (contiguity(mid) >= target)
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo > 0 && std::abs(contiguity(lo - 1) - target) < std::abs(contiguity(lo) - target) ? lo - 1 : lo;
}

}  // namespace grainmesh
