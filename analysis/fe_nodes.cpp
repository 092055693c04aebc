// CHOLMOD (through Eigen) is included here only: fe_nodes.hpp shows our own types.
#include "analysis/fe_nodes.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>
#include <unordered_map>

#include "common/errors.hpp"

namespace grainmesh {

const std::vector<Vec2>& mesh_points(const ExportMesh<2>& m) { return m.mesh.points; }
const std::vector<Vec3>& mesh_points(const ExportMesh<3>& m) { return m.mesh.points; }
std::size_t element_count(const ExportMesh<2>& m) { return m.mesh.cells(); }
std::size_t element_count(const ExportMesh<3>& m) { return m.mesh.tets.size(); }

std::array<int, 3> element_corners(const ExportMesh<2>& m, std::size_t c) {
  const std::span<const int> ring = m.mesh.cell(c);
  if (ring.size() != 3)
    throw GeometryError("finite-element reference: cell " + std::to_string(c) + " has " + std::to_string(ring.size()) +
                        " corners; it needs triangles");
  return {ring[0], ring[1], ring[2]};
}
std::array<int, 4> element_corners(const ExportMesh<3>& m, std::size_t c) { return m.mesh.tets[c]; }

namespace {

// The nodes of a mesh's quadratic elements: its points, then one per edge.
template <int D>
struct Nodes {
  std::vector<std::array<int, Simplex<D>::kNodes>> element;  // per element, corners then edges
  std::unordered_map<std::uint64_t, int> edge;                // (low, high) point ids -> node
  std::size_t count = 0;
};

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return lo << 32 | hi;
}

template <int D>
Nodes<D> quadratic_nodes(const ExportMesh<D>& m) {
  Nodes<D> n;
  const std::size_t elements = element_count(m);
  n.count = mesh_points(m).size();
  n.element.resize(elements);
  n.edge.reserve(2 * elements);  // about 1.5 edges per triangle, 1.2 per tetrahedron
  for (std::size_t c = 0; c < elements; ++c) {
    const auto corners = element_corners(m, c);
    auto& nodes = n.element[c];
    for (int i = 0; i <= D; ++i) nodes[static_cast<std::size_t>(i)] = corners[static_cast<std::size_t>(i)];
    int k = D + 1;
    for (const auto& [i, j] : Simplex<D>::edges()) {
      const auto [it, added] = n.edge.try_emplace(edge_key(corners[static_cast<std::size_t>(i)],
                                                           corners[static_cast<std::size_t>(j)]),
                                                  static_cast<int>(n.count));
      if (added) ++n.count;
      nodes[static_cast<std::size_t>(k++)] = it->second;
    }
  }
  return n;
}

// Union-find over the nodes: the classes of nodes tied by periodicity.
class Ties {
 public:
  explicit Ties(std::size_t n) : parent_(n) {
    for (std::size_t i = 0; i < n; ++i) parent_[i] = static_cast<int>(i);
  }
  int root(int i) {
    while (parent_[static_cast<std::size_t>(i)] != i) {
      parent_[static_cast<std::size_t>(i)] = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(i)])];
      i = parent_[static_cast<std::size_t>(i)];
    }
    return i;
  }
  void tie(int a, int b) {
    a = root(a);
    b = root(b);
    if (a != b) parent_[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

// Each node's unknowns' first index (D of them), -1 for the held class (the first point's).
template <int D>
std::vector<int> node_unknowns(const ExportMesh<D>& m, const Nodes<D>& n, std::size_t& unknowns) {
  if (!m.periodic) throw GeometryError("finite-element reference: the cell is not periodic");
  Ties ties(n.count);
  for (int axis = 0; axis < D; ++axis) {
    std::unordered_map<int, int> image;
    for (const auto& [low, high] : m.pairs.axis[static_cast<std::size_t>(axis)]) {
      image[low] = high;
      ties.tie(low, high);
    }
    // An edge on the low side and the image edge: their midside nodes are images too.
    for (const auto& [key, node] : n.edge) {
      const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
      const auto ia = image.find(a), ib = image.find(b);
      if (ia == image.end() || ib == image.end()) continue;
      const auto other = n.edge.find(edge_key(ia->second, ib->second));
      if (other == n.edge.end())
        throw GeometryError("finite-element reference: the edge of points " + std::to_string(a) + " and " +
                            std::to_string(b) + " on a low side has no image edge");
      ties.tie(node, other->second);
    }
  }
  // A class no element uses has no stiffness and no unknowns (a point the mesher left
  // unused); the held class is the first used point's.
  std::vector<char> used(n.count, 0);
  for (const auto& element : n.element)
    for (const int node : element) used[static_cast<std::size_t>(ties.root(node))] = 1;
  std::vector<int> cls(n.count, -1), first(n.count, -1);
  int held = -1;
  for (const auto& element : n.element) {
    held = ties.root(element[0]);
    break;
  }
  int next = 0;
  for (std::size_t i = 0; i < n.count; ++i) {
    const int r = ties.root(static_cast<int>(i));
    if (r == held || used[static_cast<std::size_t>(r)] == 0) continue;
    if (cls[static_cast<std::size_t>(r)] < 0) cls[static_cast<std::size_t>(r)] = next++;
    first[i] = D * cls[static_cast<std::size_t>(r)];
  }
  unknowns = static_cast<std::size_t>(D) * static_cast<std::size_t>(next);
  return first;
}

constexpr double kLast = std::numeric_limits<double>::infinity();

// The unknown nodes' class (first[node] / D), -1 for none.
int class_of(const std::vector<int>& first, int node, int d) {
  return first[static_cast<std::size_t>(node)] < 0 ? -1 : first[static_cast<std::size_t>(node)] / d;
}

// Each corner class's place in a fill-reducing order made on the mesh's corners alone, a
// graph a tenth the size of the nodes' (2D): CHOLMOD's analysis of the corners' graph
// (its nested dissection); classes that are no corner's stay kLast.
template <int D>
std::vector<double> corner_places(const Nodes<D>& n, std::size_t classes, const std::vector<int>& first) {
  std::vector<int> corner_index(classes, -1), corner_class;
  for (const auto& element : n.element)
    for (int i = 0; i <= D; ++i)
      if (const int c = class_of(first, element[static_cast<std::size_t>(i)], D);
          c >= 0 && corner_index[static_cast<std::size_t>(c)] < 0) {
        corner_index[static_cast<std::size_t>(c)] = static_cast<int>(corner_class.size());
        corner_class.push_back(c);
      }
  std::vector<Eigen::Triplet<double>> pairs;
  pairs.reserve(n.element.size() * (D + 1) * (D + 2) / 2);
  for (const auto& element : n.element)
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j <= D; ++j) {
        const int a = class_of(first, element[static_cast<std::size_t>(i)], D);
        const int b = class_of(first, element[static_cast<std::size_t>(j)], D);
        if (a < 0 || b < 0) continue;
        const int ia = corner_index[static_cast<std::size_t>(a)], ib = corner_index[static_cast<std::size_t>(b)];
        if (ia >= ib) pairs.emplace_back(ia, ib, 1.0);
      }
  const auto corners = static_cast<int>(corner_class.size());
  Eigen::SparseMatrix<double> graph(corners, corners);
  graph.setFromTriplets(pairs.begin(), pairs.end());
  const Eigen::SparseMatrix<double>& lower = graph;
  cholmod_sparse view = Eigen::viewAsCholmod(lower.selfadjointView<Eigen::Lower>());
  cholmod_common common;
  cholmod_start(&common);
  common.nmethods = 1;  // CHOLMOD's nested dissection: the fewest operations measured (2D 1,000 grains: 2.2e10
  common.method[0].ordering = CHOLMOD_NESDIS;  // against METIS's 2.5e10 and AMD's 5.3e10; 3D: 2.2e12 against 2.5e12)
  cholmod_factor* symbolic = cholmod_analyze(&view, &common);
  if (symbolic == nullptr) {
    cholmod_finish(&common);
    throw GeometryError("finite-element reference: CHOLMOD could not order the unknowns");
  }
  std::vector<double> place(classes, kLast);
  const auto* order = static_cast<const int*>(symbolic->Perm);  // order[new] = old
  for (int k = 0; k < corners; ++k) place[static_cast<std::size_t>(corner_class[static_cast<std::size_t>(order[k])])] = k;
  cholmod_free_factor(&symbolic, &common);
  cholmod_finish(&common);
  return place;
}

// The same for a nested split of the coarse level `coarse` (element 2^D c + k inside
// coarse element c): its corners are the coarse level's nodes, each placed where the coarse
// level numbered that node's unknowns (an order made for the coarse factor, at no cost).
template <int D>
std::vector<double> nested_places(const ExportMesh<D>& m, const Nodes<D>& n, std::size_t classes,
                                  const std::vector<int>& first, const ExportMesh<D>& coarse,
                                  const FeNodes<D>& coarse_nodes) {
  using Point = std::remove_cvref_t<decltype(mesh_points(m)[0])>;
  constexpr auto edges = Simplex<D>::edges();
  const auto& points = mesh_points(m);
  const auto& coarse_points = mesh_points(coarse);
  std::vector<double> place(classes, kLast);
  for (std::size_t f = 0; f < n.element.size(); ++f) {
    const std::size_t c = f >> D;
    const auto corners = element_corners(coarse, c);
    std::array<Point, Simplex<D>::kNodes> at;  // the coarse element's nodes' positions
    for (std::size_t b = 0; b <= D; ++b) at[b] = coarse_points[static_cast<std::size_t>(corners[b])];
    for (std::size_t e = 0; e < edges.size(); ++e)
      at[D + 1 + e] = 0.5 * (at[static_cast<std::size_t>(edges[e][0])] + at[static_cast<std::size_t>(edges[e][1])]);
    for (int i = 0; i <= D; ++i) {
      const int node = n.element[f][static_cast<std::size_t>(i)];
      const int k = class_of(first, node, D);
      if (k < 0) continue;
      const Point& x = points[static_cast<std::size_t>(node)];
      auto distance2 = [&](std::size_t b) { return dot(at[b] - x, at[b] - x); };
      std::size_t nearest = 0;
      for (std::size_t b = 1; b < at.size(); ++b)
        if (distance2(b) < distance2(nearest)) nearest = b;
      const int coarse_class = class_of(coarse_nodes.first, coarse_nodes.element[c][nearest], D);
      double& at_k = place[static_cast<std::size_t>(k)];
      if (coarse_class >= 0) at_k = std::min(at_k, static_cast<double>(coarse_class));
    }
  }
  return place;
}

// Numbers the unknown nodes (first[node] / D, their D components riding together) from
// their corners' places: each edge's midside node follows the first of its two corners,
// which keeps every separator a separator. The factor needs no ordering of its own.
template <int D>
void order_unknowns(const Nodes<D>& n, std::size_t unknowns, std::vector<double> place, std::vector<int>& first) {
  const auto classes = unknowns / static_cast<std::size_t>(D);
  constexpr auto edges = Simplex<D>::edges();
  for (const auto& element : n.element)
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const int c = class_of(first, element[D + 1 + e], D);
      if (c < 0) continue;
      double after = kLast;
      for (const int end : {edges[e][0], edges[e][1]})
        if (const int k = class_of(first, element[static_cast<std::size_t>(end)], D); k >= 0)
          after = std::min(after, place[static_cast<std::size_t>(k)] + 0.5);
      place[static_cast<std::size_t>(c)] = std::min(place[static_cast<std::size_t>(c)], after);
    }
  std::vector<int> by_place(classes);
  std::iota(by_place.begin(), by_place.end(), 0);
  std::stable_sort(by_place.begin(), by_place.end(), [&](int a, int b) {
    return place[static_cast<std::size_t>(a)] < place[static_cast<std::size_t>(b)];
  });
  std::vector<int> renumbered(classes);
  for (std::size_t k = 0; k < classes; ++k) renumbered[static_cast<std::size_t>(by_place[k])] = static_cast<int>(k);
  for (int& f : first)
    if (f >= 0) f = D * renumbered[static_cast<std::size_t>(f / D)];
}

template <int D>
FeNodes<D> nodes_of(const ExportMesh<D>& m, const ExportMesh<D>* coarse, const FeNodes<D>* coarse_nodes) {
  Nodes<D> n = quadratic_nodes(m);
  FeNodes<D> out;
  out.first = node_unknowns(m, n, out.unknowns);
  const std::size_t classes = out.unknowns / static_cast<std::size_t>(D);
  order_unknowns(n, out.unknowns,
                 coarse ? nested_places(m, n, classes, out.first, *coarse, *coarse_nodes)
                        : corner_places(n, classes, out.first),
                 out.first);
  out.element = std::move(n.element);
  out.count = n.count;
  return out;
}

}  // namespace

FeNodes<2> fe_nodes(const ExportMesh<2>& m) { return nodes_of<2>(m, nullptr, nullptr); }
FeNodes<3> fe_nodes(const ExportMesh<3>& m) { return nodes_of<3>(m, nullptr, nullptr); }

FeNodes<2> fe_nodes(const ExportMesh<2>& fine, const ExportMesh<2>& coarse, const FeNodes<2>& coarse_nodes) {
  return nodes_of(fine, &coarse, &coarse_nodes);
}

FeNodes<3> fe_nodes(const ExportMesh<3>& fine, const ExportMesh<3>& coarse, const FeNodes<3>& coarse_nodes) {
  return nodes_of(fine, &coarse, &coarse_nodes);
}

template <int D>
NodeGraph node_graph(const FeNodes<D>& n) {
  const std::vector<int>& first = n.first;
  const int nodes = static_cast<int>(n.unknowns) / D;
  auto node_of = [&](int node) { return class_of(first, node, D); };
  std::vector<int> start(static_cast<std::size_t>(nodes) + 1, 0), elements;
  for (const auto& element : n.element)
    for (const int a : element)
      if (const int i = node_of(a); i >= 0) ++start[static_cast<std::size_t>(i) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  elements.resize(static_cast<std::size_t>(start.back()));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t c = 0; c < n.element.size(); ++c)
    for (const int a : n.element[c])
      if (const int i = node_of(a); i >= 0)
        elements[static_cast<std::size_t>(fill[static_cast<std::size_t>(i)]++)] = static_cast<int>(c);
  NodeGraph g;
  g.outer.reserve(static_cast<std::size_t>(nodes) + 1);
  g.inner.reserve(elements.size() * Simplex<D>::kNodes / 2);
  std::vector<int> seen(static_cast<std::size_t>(nodes), -1);
  for (int j = 0; j < nodes; ++j) {
    g.outer.push_back(static_cast<int>(g.inner.size()));
    for (int e = start[static_cast<std::size_t>(j)]; e < start[static_cast<std::size_t>(j) + 1]; ++e)
      for (const int a : n.element[static_cast<std::size_t>(elements[static_cast<std::size_t>(e)])])
        if (const int i = node_of(a); i >= j && seen[static_cast<std::size_t>(i)] != j) {
          seen[static_cast<std::size_t>(i)] = j;
          g.inner.push_back(i);
        }
    std::sort(g.inner.begin() + g.outer.back(), g.inner.end());
  }
  g.outer.push_back(static_cast<int>(g.inner.size()));
  return g;
}

template NodeGraph node_graph(const FeNodes<2>&);
template NodeGraph node_graph(const FeNodes<3>&);

}  // namespace grainmesh
