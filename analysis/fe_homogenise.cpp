// Eigen and CHOLMOD are included here only (fe_homogenise.hpp shows our own types).
#include "analysis/fe_homogenise.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "analysis/bounds.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/memory.hpp"

namespace grainmesh {

namespace {

// A simplex of D dimensions with quadratic Lagrange shape functions: its D + 1 corners,
// then one node per edge (i, j), i < j, in kEdges' order.
template <int D>
struct Simplex {
  static constexpr int kCorners = D + 1;
  static constexpr int kEdges = D * (D + 1) / 2;
  static constexpr int kNodes = kCorners + kEdges;
  static constexpr std::size_t kVoigt = voigt_size(D);
  static constexpr std::array<std::array<int, 2>, kEdges> edges() {
    std::array<std::array<int, 2>, kEdges> e{};
    int k = 0;
    for (int i = 0; i < kCorners; ++i)
      for (int j = i + 1; j < kCorners; ++j) e[static_cast<std::size_t>(k++)] = {i, j};
    return e;
  }
};

double coordinate(const Vec2& p, int k) { return k == 0 ? p.x : p.y; }
double coordinate(const Vec3& p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; }

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

// Quadrature exact for polynomials of degree 2 on the simplex: barycentric points and
// weights (summing to 1; times the element's measure).
template <int D>
struct Quadrature {
  std::vector<std::array<double, D + 1>> points;
  std::vector<double> weights;
};
template <int D>
Quadrature<D> degree_two_rule() {
  Quadrature<D> q;
  // The points (a, b, ..., b) with their corners permuted: 2D a = 2/3, b = 1/6; 3D the
  // 4-point rule a = (5 + 3 sqrt 5) / 20, b = (5 - sqrt 5) / 20.
  const double a = D == 2 ? 2.0 / 3.0 : (5.0 + 3.0 * std::sqrt(5.0)) / 20.0;
  const double b = D == 2 ? 1.0 / 6.0 : (5.0 - std::sqrt(5.0)) / 20.0;
  for (int i = 0; i <= D; ++i) {
    std::array<double, D + 1> l;
    l.fill(b);
    l[static_cast<std::size_t>(i)] = a;
    q.points.push_back(l);
    q.weights.push_back(1.0 / (D + 1));
  }
  return q;
}

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
  std::vector<int> cls(n.count, -1), first(n.count, -1);
  const int held = ties.root(0);
  int next = 0;
  for (std::size_t i = 0; i < n.count; ++i) {
    const int r = ties.root(static_cast<int>(i));
    if (r == held) continue;
    if (cls[static_cast<std::size_t>(r)] < 0) cls[static_cast<std::size_t>(r)] = next++;
    first[i] = D * cls[static_cast<std::size_t>(r)];
  }
  unknowns = static_cast<std::size_t>(D) * static_cast<std::size_t>(next);
  return first;
}

template <int D>
using BMatrix = Eigen::Matrix<double, static_cast<int>(voigt_size(D)), D * Simplex<D>::kNodes>;
template <int D>
using VoigtMatrix = Eigen::Matrix<double, static_cast<int>(voigt_size(D)), static_cast<int>(voigt_size(D))>;
template <int D>
using VoigtVector = Eigen::Matrix<double, static_cast<int>(voigt_size(D)), 1>;

// One element's geometry: its measure and, at each quadrature point, the strain matrix B
// (Voigt rows, engineering shears; columns node by node, D components each).
template <int D>
struct ElementGeometry {
  double measure = 0.0;
  std::vector<BMatrix<D>> b;
};

template <int D>
ElementGeometry<D> element_geometry(const ExportMesh<D>& m, std::size_t c, const Quadrature<D>& q) {
  const auto corners = element_corners(m, c);
  const auto& points = mesh_points(m);
  Eigen::Matrix<double, D, D> jacobian;  // column k: corner k + 1 less corner 0
  for (int k = 0; k < D; ++k)
    for (int r = 0; r < D; ++r)
      jacobian(r, k) = coordinate(points[static_cast<std::size_t>(corners[static_cast<std::size_t>(k + 1)])], r) -
                       coordinate(points[static_cast<std::size_t>(corners[0])], r);
  const double det = jacobian.determinant();
  if (!(det > 0.0))
    throw GeometryError("finite-element reference: element " + std::to_string(c) + " is inverted or flat");
  ElementGeometry<D> g;
  g.measure = det / (D == 2 ? 2.0 : 6.0);
  // Row k of J^-1 is the gradient of barycentric coordinate k + 1; corner 0's is minus their sum.
  const Eigen::Matrix<double, D, D> inverse = jacobian.inverse();
  std::array<Eigen::Matrix<double, D, 1>, D + 1> grad;
  grad[0].setZero();
  for (int k = 0; k < D; ++k) {
    grad[static_cast<std::size_t>(k + 1)] = inverse.row(k).transpose();
    grad[0] -= grad[static_cast<std::size_t>(k + 1)];
  }
  constexpr auto edges = Simplex<D>::edges();
  for (const auto& l : q.points) {
    std::array<Eigen::Matrix<double, D, 1>, Simplex<D>::kNodes> dn;
    for (int i = 0; i <= D; ++i)
      dn[static_cast<std::size_t>(i)] = (4.0 * l[static_cast<std::size_t>(i)] - 1.0) * grad[static_cast<std::size_t>(i)];
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const auto i = static_cast<std::size_t>(edges[e][0]), j = static_cast<std::size_t>(edges[e][1]);
      dn[D + 1 + e] = 4.0 * (l[i] * grad[j] + l[j] * grad[i]);
    }
    BMatrix<D> b = BMatrix<D>::Zero();
    for (int a = 0; a < Simplex<D>::kNodes; ++a) {
      const auto& d = dn[static_cast<std::size_t>(a)];
      const int x = D * a, y = x + 1;
      if constexpr (D == 2) {  // xx, yy, xy
        b(0, x) = d(0);
        b(1, y) = d(1);
        b(2, x) = d(1);
        b(2, y) = d(0);
      } else {  // xx, yy, zz, yz, xz, xy
        const int z = x + 2;
        b(0, x) = d(0);
        b(1, y) = d(1);
        b(2, z) = d(2);
        b(3, y) = d(2);
        b(3, z) = d(1);
        b(4, x) = d(2);
        b(4, z) = d(0);
        b(5, x) = d(1);
        b(5, y) = d(0);
      }
    }
    g.b.push_back(b);
  }
  return g;
}

// Each phase's Voigt stiffness and its free thermal strain under a unit temperature change.
template <int D>
struct Materials {
  std::vector<VoigtMatrix<D>> stiffness;
  std::vector<VoigtVector<D>> thermal_strain;
};

template <int D>
Materials<D> materials(const ExportMesh<D>& m, bool plane_stress) {
  constexpr std::size_t N = voigt_size(D);
  Materials<D> out;
  for (const FoamPhase& p : m.phases) {
    const Stiffness<N> c = isotropic_stiffness<N>(p, plane_stress);
    VoigtMatrix<D> s;
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j) s(static_cast<int>(i), static_cast<int>(j)) = c[i][j];
    out.stiffness.push_back(s);
    VoigtVector<D> e = VoigtVector<D>::Zero();
    for (int k = 0; k < D; ++k) e(k) = D == 2 ? free_expansion(p, plane_stress) : p.alpha;
    out.thermal_strain.push_back(e);
  }
  return out;
}

// The graph of the unknown nodes (first[node] / D) that share an element: its lower
// triangle, diagonal included, rows sorted in each column.
template <int D>
Eigen::SparseMatrix<double> node_graph(const Nodes<D>& n, std::size_t unknowns, const std::vector<int>& first) {
  const int nodes = static_cast<int>(unknowns) / D;
  std::vector<Eigen::Triplet<double>> pairs;
  pairs.reserve(n.element.size() * Simplex<D>::kNodes * (Simplex<D>::kNodes + 1) / 2);
  for (const auto& element : n.element)
    for (const int a : element)
      for (const int b : element) {
        const int i = first[static_cast<std::size_t>(a)], j = first[static_cast<std::size_t>(b)];
        if (i >= 0 && j >= 0 && i >= j) pairs.emplace_back(i / D, j / D, 1.0);
      }
  Eigen::SparseMatrix<double> graph(nodes, nodes);
  graph.setFromTriplets(pairs.begin(), pairs.end());
  return graph;
}

// Numbers the unknown nodes (first[node] / D, their D components riding together) in a
// fill-reducing order made on the mesh's corners alone, a graph a tenth the size of the
// nodes' (2D): CHOLMOD's analysis of the corners' graph (AMD, or METIS's nested dissection
// where it does better); each edge's midside node then follows the first of its two
// corners, which keeps every separator a separator. The factor needs no ordering of its own.
template <int D>
void order_unknowns(const Nodes<D>& n, std::size_t unknowns, std::vector<int>& first) {
  const auto classes = unknowns / static_cast<std::size_t>(D);
  auto class_of = [&](int node) { return first[static_cast<std::size_t>(node)] < 0 ? -1 : first[static_cast<std::size_t>(node)] / D; };
  std::vector<int> corner_index(classes, -1), corner_class;
  for (const auto& element : n.element)
    for (int i = 0; i <= D; ++i)
      if (const int c = class_of(element[static_cast<std::size_t>(i)]); c >= 0 && corner_index[static_cast<std::size_t>(c)] < 0) {
        corner_index[static_cast<std::size_t>(c)] = static_cast<int>(corner_class.size());
        corner_class.push_back(c);
      }
  std::vector<Eigen::Triplet<double>> pairs;
  pairs.reserve(n.element.size() * (D + 1) * (D + 2) / 2);
  for (const auto& element : n.element)
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j <= D; ++j) {
        const int a = class_of(element[static_cast<std::size_t>(i)]), b = class_of(element[static_cast<std::size_t>(j)]);
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
  // Each class's place: a corner's its position in the order, a midside node's just after
  // the first of its corners (a class of nodes, images of one another: the first of all).
  constexpr double kLast = std::numeric_limits<double>::infinity();
  std::vector<double> place(classes, kLast);
  const auto* order = static_cast<const int*>(symbolic->Perm);  // order[new] = old
  for (int k = 0; k < corners; ++k) place[static_cast<std::size_t>(corner_class[static_cast<std::size_t>(order[k])])] = k;
  cholmod_free_factor(&symbolic, &common);
  cholmod_finish(&common);
  constexpr auto edges = Simplex<D>::edges();
  for (const auto& element : n.element)
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const int c = class_of(element[D + 1 + e]);
      if (c < 0) continue;
      double after = kLast;
      for (const int end : {edges[e][0], edges[e][1]})
        if (const int k = class_of(element[static_cast<std::size_t>(end)]); k >= 0)
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

// The discrete problem: the mesh's quadratic nodes, each node's unknowns, the phases'
// materials, the quadrature and the loads — load j < N the unit macroscopic (engineering)
// strain j, load N (when thermal) the unit temperature change.
template <int D>
struct Problem {
  static constexpr std::size_t N = voigt_size(D);
  static constexpr int kDofs = D * Simplex<D>::kNodes;
  const ExportMesh<D>& m;
  Nodes<D> nodes;
  std::size_t unknowns = 0;  // before `first`, which counts them
  std::vector<int> first;
  Materials<D> mat;
  Quadrature<D> q;
  int loads = 0;

  Problem(const ExportMesh<D>& mesh, bool plane_stress, bool thermal)
      : m(mesh), nodes(quadratic_nodes(mesh)), first(node_unknowns(mesh, nodes, unknowns)),
        mat(materials(mesh, plane_stress)), q(degree_two_rule<D>()), loads(static_cast<int>(N) + (thermal ? 1 : 0)) {
    order_unknowns(nodes, unknowns, first);
  }

  // The strain load j imposes on a phase: E_j, or minus its free thermal strain.
  VoigtVector<D> imposed(int phase, int j) const {
    if (j < static_cast<int>(N)) return VoigtVector<D>::Unit(j);
    return -mat.thermal_strain[static_cast<std::size_t>(phase)];
  }
  // The unknown of element c's local degree of freedom k (node k / D, component k % D);
  // -1 when held.
  int dof(std::size_t c, int k) const {
    const int base = first[static_cast<std::size_t>(nodes.element[c][static_cast<std::size_t>(k / D)])];
    return base < 0 ? -1 : base + k % D;
  }
};

// The stiffness matrix's lower triangle with its pattern made first, from the node graph
// (each node pair's D x D block, the diagonal blocks' lower half), its entries zero.
template <int D>
Eigen::SparseMatrix<double> stiffness_pattern(const Problem<D>& p) {
  const Eigen::SparseMatrix<double> graph = node_graph(p.nodes, p.unknowns, p.first);
  const auto n = static_cast<Eigen::Index>(p.unknowns);
  Eigen::SparseMatrix<double> k(n, n);
  k.resizeNonZeros(static_cast<Eigen::Index>(D * D) * graph.nonZeros());  // an upper bound, trimmed below
  int* outer = k.outerIndexPtr();
  int* inner = k.innerIndexPtr();
  int next = 0;
  for (int j = 0; j < graph.outerSize(); ++j)
    for (int cj = 0; cj < D; ++cj) {
      outer[D * j + cj] = next;
      for (Eigen::SparseMatrix<double>::InnerIterator it(graph, j); it; ++it)
        for (int ci = 0; ci < D; ++ci)
          if (const int row = D * static_cast<int>(it.row()) + ci; row >= D * j + cj) inner[next++] = row;
    }
  outer[n] = next;
  k.resizeNonZeros(next);
  std::fill(k.valuePtr(), k.valuePtr() + next, 0.0);
  return k;
}

// The stiffness matrix (its lower triangle) and each load's right-hand side: each
// element's entries added in place into the pattern.
template <int D>
std::pair<Eigen::SparseMatrix<double>, Eigen::MatrixXd> assemble(const Problem<D>& p) {
  constexpr int kDofs = Problem<D>::kDofs;
  Eigen::SparseMatrix<double> k = stiffness_pattern(p);
  const int* outer = k.outerIndexPtr();
  const int* inner = k.innerIndexPtr();
  double* value = k.valuePtr();
  Eigen::MatrixXd f = Eigen::MatrixXd::Zero(k.rows(), p.loads);
  for (std::size_t c = 0; c < element_count(p.m); ++c) {
    const ElementGeometry<D> g = element_geometry(p.m, c, p.q);
    const int phase = p.m.phase[c];
    Eigen::Matrix<double, kDofs, kDofs> ke = Eigen::Matrix<double, kDofs, kDofs>::Zero();
    Eigen::Matrix<double, kDofs, Eigen::Dynamic> fe = Eigen::Matrix<double, kDofs, Eigen::Dynamic>::Zero(kDofs, p.loads);
    for (std::size_t i = 0; i < p.q.weights.size(); ++i) {
      const Eigen::Matrix<double, kDofs, static_cast<int>(Problem<D>::N)> btc =
          p.q.weights[i] * g.measure * g.b[i].transpose() * p.mat.stiffness[static_cast<std::size_t>(phase)];
      ke.noalias() += btc * g.b[i];
      for (int j = 0; j < p.loads; ++j) fe.col(j).noalias() -= btc * p.imposed(phase, j);
    }
    std::array<int, kDofs> dofs;
    for (int a = 0; a < kDofs; ++a) dofs[static_cast<std::size_t>(a)] = p.dof(c, a);
    for (int a = 0; a < kDofs; ++a) {
      const int r = dofs[static_cast<std::size_t>(a)];
      if (r < 0) continue;
      f.row(r) += fe.row(a);
      for (int b = 0; b < kDofs; ++b)
        if (const int s = dofs[static_cast<std::size_t>(b)]; s >= 0 && s <= r)
          value[std::lower_bound(inner + outer[s], inner + outer[s + 1], r) - inner] += ke(a, b);
    }
  }
  return {std::move(k), std::move(f)};
}

// Each load's volume-averaged stress (a column each) from the solved fluctuations `u`.
template <int D>
Eigen::MatrixXd mean_stresses(const Problem<D>& p, const Eigen::MatrixXd& u) {
  constexpr int kDofs = Problem<D>::kDofs;
  Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(static_cast<int>(Problem<D>::N), p.loads);
  double volume = 0.0;
  for (std::size_t c = 0; c < element_count(p.m); ++c) {
    const ElementGeometry<D> g = element_geometry(p.m, c, p.q);
    const int phase = p.m.phase[c];
    Eigen::Matrix<double, kDofs, Eigen::Dynamic> ue = Eigen::Matrix<double, kDofs, Eigen::Dynamic>::Zero(kDofs, p.loads);
    for (int a = 0; a < kDofs; ++a)
      if (const int r = p.dof(c, a); r >= 0) ue.row(a) = u.row(r);
    volume += g.measure;
    for (std::size_t i = 0; i < p.q.weights.size(); ++i)
      for (int j = 0; j < p.loads; ++j)
        mean.col(j) += p.q.weights[i] * g.measure * p.mat.stiffness[static_cast<std::size_t>(phase)] *
                       (g.b[i] * ue.col(j) + p.imposed(phase, j));
  }
  return mean / volume;
}

// Refuses a factor that would not fit: CHOLMOD's count of its nonzeros (known after the
// analysis, before any is made), 8 bytes each and 60 % more for the supernodes' padding
// and CHOLMOD's workspace, beside the matrix (three copies) and the loads' columns (right
// sides and solutions). On the 3D example: 4.9 GiB estimated, 5.2 GiB measured (the
// run's peak, OpenFOAM's stage included).
void check_memory(const cholmod_common& analysed, const Eigen::SparseMatrix<double>& k, int loads, std::size_t unknowns,
                  const FeOptions& o) {
  constexpr double kMiB = 1024.0 * 1024.0;
  const double need = (1.6 * 8.0 * analysed.lnz + 3.0 * 12.0 * static_cast<double>(k.nonZeros()) +
                       3.0 * 8.0 * static_cast<double>(loads) * static_cast<double>(unknowns)) / kMiB;
  const double have = o.memory_mib > 0.0 ? o.memory_mib : available_memory_mib();
  auto size = [](double mib) { return mib < 1024.0 ? to_text(mib, 3) + " MiB" : to_text(mib / 1024.0, 3) + " GiB"; };
  if (need > have)
    throw ConfigError("homogenise.reference = fe: the finite-element reference of this mesh (" +
                      std::to_string(unknowns) + " unknowns) needs about " + size(need) + ", more than the " +
                      size(have) + " available: set homogenise.reference = none, or mesh coarser or fewer grains");
}

template <int D>
FeHomogenised<voigt_size(D)> homogenise(const ExportMesh<D>& m, bool plane_stress, bool thermal, const FeOptions& o) {
  constexpr std::size_t N = voigt_size(D);
  const auto start = std::chrono::steady_clock::now();
  const Problem<D> p(m, plane_stress, thermal);
  const auto [k, f] = assemble(p);
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> solver;
  solver.cholmod().nmethods = 1;  // the unknowns are numbered in a fill-reducing order (order_unknowns)
  solver.cholmod().method[0].ordering = CHOLMOD_NATURAL;
  solver.analyzePattern(k);
  check_memory(solver.cholmod(), k, p.loads, p.unknowns, o);
  solver.factorize(k);
  if (solver.info() != Eigen::Success)
    throw GeometryError("finite-element reference: the stiffness matrix is not positive definite (a phase without "
                        "stiffness, or a mesh the periodic ties do not hold)");
  const Eigen::MatrixXd u = solver.solve(f);
  const Eigen::MatrixXd mean = mean_stresses(p, u);
  FeHomogenised<N> out;
  out.unknowns = p.unknowns;
  VoigtMatrix<D> c_eff = mean.leftCols(static_cast<int>(N));
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) out.stiffness[i][j] = c_eff(static_cast<int>(i), static_cast<int>(j));
  if (thermal) {
    // Free on average: the mean strain e with C e + sigma_T = 0, sigma_T the unit change's
    // mean stress at zero mean strain; its shears engineering, reported as tensor components.
    const VoigtVector<D> e = -c_eff.lu().solve(mean.col(static_cast<int>(N)));
    std::array<double, N> alpha{};
    for (std::size_t i = 0; i < N; ++i) alpha[i] = e(static_cast<int>(i)) * (i < static_cast<std::size_t>(D) ? 1.0 : 0.5);
    out.expansion = alpha;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace

FeHomogenised<3> fe_homogenise(const ExportMesh<2>& m, bool plane_stress, bool thermal, const FeOptions& o) {
  return homogenise(m, plane_stress, thermal, o);
}

FeHomogenised<6> fe_homogenise(const ExportMesh<3>& m, bool thermal, const FeOptions& o) {
  return homogenise(m, false, thermal, o);
}

}  // namespace grainmesh
