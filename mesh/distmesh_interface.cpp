#include "mesh/distmesh_engine.hpp"

#include <algorithm>

namespace grainmesh::distmesh_detail {

// Algorithm 3's choice for a bar crossing the interface: the end nearer to it, unless
// that end is fixed; -1 when both are.
int Engine::interface_mover(int a, int b, const std::vector<double>& di) const {
  const int k = std::abs(di[a]) <= std::abs(di[b]) ? a : b;
  if (static_cast<std::size_t>(k) >= p_.fixed()) return k;
  const int other = k == a ? b : a;
  return static_cast<std::size_t>(other) >= p_.fixed() ? other : -1;
}

// Algorithm 3: for each bar whose ends lie on opposite sides of dI = 0, the end nearer
// to the interface is projected onto it. Beyond the thesis, a point once on the
// interface stays there: it is projected back after every move, so it slides along the
// interface instead of leaving it and being caught again.
void Engine::follow_interface() {
  const DistanceFunction& di = *pb_.interface;
  di_.resize(p_.size());
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (p_.on_interface(i) && i >= p_.fixed()) p_[i] = project_to_zero(di, p_[i], deps_, proj_tol_);
    di_[i] = p_.on_interface(i) ? 0.0 : di(p_[i]);
  }
  for (const auto& bar : bars_) {
    const int a = bar[0], b = bar[1];
    if (!((di_[a] > 0.0 && di_[b] < 0.0) || (di_[a] < 0.0 && di_[b] > 0.0))) continue;
    const int k = interface_mover(a, b, di_);
    if (k < 0) continue;
    p_[k] = project_to_zero(di, p_[k], deps_, proj_tol_);
    di_[k] = 0.0;
    p_.hold_on_interface(k);
  }
}

// After the last triangulation: triangles whose corners lie on opposite sides of the
// interface get the Algorithm 3 treatment on their crossing edges, and the mesh is
// triangulated again, until none is left (or the pass limit). Returns how many remain.
std::size_t Engine::repair_interface() {
  const DistanceFunction& di = *pb_.interface;
  for (int pass = 0;; ++pass) {
    di_.resize(p_.size());
    for (std::size_t i = 0; i < p_.size(); ++i) di_[i] = di(p_[i]);
    auto side = [&](int v) { return di_[v] > on_interface_tol_ ? 1 : (di_[v] < -on_interface_tol_ ? -1 : 0); };
    std::vector<int> movers;
    std::size_t straddling = 0;
    for (const auto& t : tris_) {
      int lo = 1, hi = -1;
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        lo = std::min(lo, side(a));
        hi = std::max(hi, side(a));
        if (side(a) * side(b) >= 0) continue;
        if (const int m = interface_mover(a, b, di_); m >= 0) movers.push_back(m);
      }
      straddling += (lo < 0 && hi > 0);
    }
    if (straddling == 0 || movers.empty() || pass == 20) return straddling;
    std::sort(movers.begin(), movers.end());
    movers.erase(std::unique(movers.begin(), movers.end()), movers.end());
    for (int m : movers) {
      p_[m] = project_to_zero(di, p_[m], deps_, proj_tol_);
      p_.hold_on_interface(m);
    }
    ++stats_.interface_repairs;
    triangulate();
  }
}


}  // namespace grainmesh::distmesh_detail
