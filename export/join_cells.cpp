// Joining cells checkMesh would fail with neighbours of their grain (join_cells.hpp).
//
// The joins are chosen on the polyMesh as it is, without building it again: a joined
// cell's volume is its parts' sum and its centre their mean by volume, as OpenFOAM's
// pyramids give them for plane faces (the dual's faces round an edge bend a little, so the
// builder checks the rebuilt mesh again), and its faces are its parts' faces but those
// between them.
#include "export/join_cells.hpp"

#include <algorithm>
#include <numeric>

#include "export/foam_mesh_check.hpp"

namespace grainmesh {

namespace {

// Each cell's faces (an internal face in both its cells' lists), as offsets into one list.
struct CellFaces {
  std::vector<int> start, faces;
  explicit CellFaces(const PolyMesh& pm) : start(static_cast<std::size_t>(pm.cells) + 1, 0) {
    for (int f = 0; f < pm.faces(); ++f) {
      ++start[pm.owner[f] + 1];
      if (f < pm.internal_faces()) ++start[pm.neighbour[f] + 1];
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    faces.resize(static_cast<std::size_t>(start.back()));
    std::vector<int> next(start.begin(), start.end() - 1);
    for (int f = 0; f < pm.faces(); ++f) {
      faces[next[pm.owner[f]]++] = f;
      if (f < pm.internal_faces()) faces[next[pm.neighbour[f]]++] = f;
    }
  }
  auto of(int c) const { return std::pair{faces.begin() + start[c], faces.begin() + start[c + 1]}; }
};

// A failing cell counts as many failing faces (any join that mends it is taken).
constexpr int kCellFailure = 1000;

// Cells joined so far: each set named by its lowest cell (its root), with its parts, volume
// and centre.
class Joiner {
 public:
  Joiner(const PolyMesh& pm, const std::vector<int>& grain, const std::vector<int>& phase, const std::vector<Vec3>& centre,
         const std::vector<double>& volume, const FoamCheckFailures& failures)
      : pm_(pm), grain_(grain), phase_(phase), check_(pm, centre, volume), faces_(pm), parent_(grain.size()),
        parts_(grain.size()), centre_(centre), volume_(volume), failing_(grain.size(), 0) {
    std::iota(parent_.begin(), parent_.end(), 0);
    for (std::size_t c = 0; c < parts_.size(); ++c) parts_[c] = {static_cast<int>(c)};
    for (int c : failures.cells) failing_[c] = 1;
    for (std::size_t c = 0; c < failing_.size(); ++c)
      if (failing_[c]) work_.push_back(-1 - static_cast<int>(c));
    work_.insert(work_.end(), failures.faces.begin(), failures.faces.end());
  }

  // Works through the failing faces and cells, joining where that reduces the failures
  // (a join's new cell's failing faces back on the list); true when anything was joined.
  bool run() {
    bool joined = false;
    while (!work_.empty()) {
      const int item = work_.back();
      work_.pop_back();
      int x = 0, z = -1;
      if (item < 0) {
        x = root(-1 - item);
        if (!failing_[x]) continue;
      } else {
        x = root(pm_.owner[item]);
        z = other_root(item);
        if (z == x || !fails(item, {})) continue;  // joined away, or passing now
        if (item >= pm_.internal_faces()) z = -1;           // never across a cyclic pair
        if (z >= 0 && volume_[z] < volume_[x]) std::swap(x, z);  // the smaller side first
      }
      if (join_best(x, z, false) || join_best(x, z, true)) joined = true;
    }
    return joined;
  }

  int root(int c) {
    while (parent_[c] != c) c = parent_[c] = parent_[parent_[c]];
    return c;
  }

 private:
  // Cells (roots) to join, each with its group (0 or 1): a group's cells become one.
  struct Trial {
    std::vector<int> cell, group;
  };

  int other_root(int f) {
    const int o = check_.other(f);
    return o < 0 ? -1 : root(o);
  }

  // Joins x with roots of its grain (of its phase when `across_grains`) across its
  // internal faces, and z (when >= 0) with its own: one each, all of them, or nothing on
  // one side, whichever most reduces the failures on their faces.
  bool join_best(int x, int z, bool across_grains) {
    const std::vector<std::vector<int>> xs = choices(x, across_grains);
    const std::vector<std::vector<int>> zs = z >= 0 ? choices(z, across_grains) : std::vector<std::vector<int>>{{}};
    Trial best;
    int gain = 0;
    for (const auto& ys : xs)
      for (const auto& ws : zs) {
        if (ys.empty() && ws.empty()) continue;
        Trial t{{x}, {0}};
        for (int y : ys) t.cell.push_back(y), t.group.push_back(0);
        if (z >= 0) t.cell.push_back(z), t.group.push_back(1);
        for (int w : ws) t.cell.push_back(w), t.group.push_back(1);
        const int g = failures(t, false) - failures(t, true);
        if (g > gain) {
          gain = g;
          best = std::move(t);
        }
      }
    if (best.cell.empty()) return false;
    for (std::size_t i = 1; i < best.cell.size(); ++i)
      if (best.group[i] == best.group[i - 1]) join(best.cell[i - 1], best.cell[i]);
    for (int g : {0, 1}) {
      const auto it = std::find(best.group.begin(), best.group.end(), g);
      if (it == best.group.end()) continue;
      const int r = root(best.cell[static_cast<std::size_t>(it - best.group.begin())]);
      for_each_face(r, [&](int f) { work_.push_back(f); });
    }
    return true;
  }

  void join(int a, int b) {
    a = root(a);
    b = root(b);
    if (a == b) return;
    if (b < a) std::swap(a, b);
    const double v = volume_[a] + volume_[b];
    if (v > 0.0) centre_[a] = (volume_[a] * centre_[a] + volume_[b] * centre_[b]) / v;
    volume_[a] = v;
    failing_[a] = 0;
    parts_[a].insert(parts_[a].end(), parts_[b].begin(), parts_[b].end());
    parts_[b].clear();
    parent_[b] = a;
  }

  // Visits each face of root r once: its parts' faces but those between two of them.
  template <class Visit>
  void for_each_face(int r, Visit&& visit) {
    for (int c : parts_[r]) {
      const auto [begin, end] = faces_.of(c);
      for (auto it = begin; it != end; ++it)
        if (*it >= pm_.internal_faces() || root(pm_.owner[*it]) != root(pm_.neighbour[*it])) visit(*it);
    }
  }

  // What c may be joined with: nothing, each root of its grain (or phase) across its
  // internal faces, all of them.
  std::vector<std::vector<int>> choices(int c, bool across_grains) {
    std::vector<int> all;
    for_each_face(c, [&](int f) {
      if (f >= pm_.internal_faces()) return;
      const int a = root(pm_.owner[f]), b = root(pm_.neighbour[f]);
      const int y = a == c ? b : a;
      const bool same = across_grains ? phase_[y] == phase_[c] : grain_[y] == grain_[c];
      if (same && std::find(all.begin(), all.end(), y) == all.end()) all.push_back(y);
    });
    std::vector<std::vector<int>> out{{}};
    for (int y : all) out.push_back({y});
    if (all.size() > 1) out.push_back(all);
    return out;
  }

  // Whether face f fails with the centres of the roots in `moved` replaced.
  bool fails(int f, const std::vector<std::pair<int, Vec3>>& moved) {
    auto at = [&](int r) {
      for (const auto& [c, p] : moved)
        if (c == r) return p;
      return centre_[r];
    };
    const int o = other_root(f);
    return check_.fails(f, at(root(pm_.owner[f])), o >= 0 ? check_.across(f, at(o)) : Vec3{});
  }

  // The failing faces of the trial's cells and the failing cells among them, as they are
  // or `joined` (a group's centre the mean of its cells' by volume, the faces between them
  // inside it).
  int failures(const Trial& t, bool joined) {
    std::vector<std::pair<int, Vec3>> moved;
    if (joined)
      for (int g : {0, 1}) {
        Vec3 sum{};
        double v = 0.0;
        for (std::size_t i = 0; i < t.cell.size(); ++i)
          if (t.group[i] == g) sum += volume_[t.cell[i]] * centre_[t.cell[i]], v += volume_[t.cell[i]];
        if (v > 0.0)
          for (std::size_t i = 0; i < t.cell.size(); ++i)
            if (t.group[i] == g) moved.push_back({t.cell[i], sum / v});
      }
    auto index = [&](int r) { return static_cast<std::size_t>(std::find(t.cell.begin(), t.cell.end(), r) - t.cell.begin()); };
    int n = 0;
    for (std::size_t i = 0; i < t.cell.size(); ++i) {
      const int c = t.cell[i];
      if (!joined) n += kCellFailure * failing_[c];
      for_each_face(c, [&](int f) {
        const int a = root(pm_.owner[f]), b = other_root(f);
        const std::size_t j = index(a == c ? b : a);
        if (f < pm_.internal_faces() && j < t.cell.size()) {
          if (j < i) return;                                 // counted from that cell
          if (joined && t.group[j] == t.group[i]) return;  // inside a joined group
        }
        n += fails(f, moved);
      });
    }
    return n;
  }

  const PolyMesh& pm_;
  const std::vector<int>& grain_;
  const std::vector<int>& phase_;
  FoamMeshCheck check_;
  CellFaces faces_;
  std::vector<int> parent_;
  std::vector<std::vector<int>> parts_;
  std::vector<Vec3> centre_;     // per root
  std::vector<double> volume_;   // per root
  std::vector<char> failing_;    // per root: its volume or aspect ratio fails
  std::vector<int> work_;        // faces, and failing cells c as -1 - c
};

}  // namespace

std::vector<int> joined_cells(const PolyMesh& pm, const std::vector<int>& grain, const std::vector<int>& phase,
                              const std::vector<Vec3>& centre, const std::vector<double>& volume,
                              const FoamCheckFailures& failures) {
  Joiner joiner(pm, grain, phase, centre, volume, failures);
  if (!joiner.run()) return {};
  std::vector<int> number(static_cast<std::size_t>(pm.cells), -1);
  int next = 0;
  for (int c = 0; c < pm.cells; ++c) {
    const int r = joiner.root(c);
    if (number[r] < 0) number[r] = next++;
    number[c] = number[r];
  }
  return number;
}

void join_cells(const std::vector<int>& number, const FoamMesh3& built, FoamMesh3& cells) {
  const int count = *std::max_element(number.begin(), number.end()) + 1;
  cells.grain.assign(static_cast<std::size_t>(count), 0);
  cells.phase.assign(static_cast<std::size_t>(count), 0);
  std::vector<double> largest(static_cast<std::size_t>(count), -1.0);
  for (std::size_t c = 0; c < number.size(); ++c)
    if (built.volume[c] > largest[number[c]]) {
      largest[number[c]] = built.volume[c];
      cells.grain[number[c]] = built.grain[c];
      cells.phase[number[c]] = built.phase[c];
    }
  for (int& c : cells.corner_cell) c = number[c];
}

}  // namespace grainmesh
