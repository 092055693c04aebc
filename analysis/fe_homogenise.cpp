// Eigen and CHOLMOD are included here only (fe_homogenise.hpp shows our own types).
#include "analysis/fe_homogenise.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "analysis/bounds.hpp"
#include "analysis/fe_nodes.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/memory.hpp"

namespace grainmesh {

namespace {

double coordinate(const Vec2& p, int k) { return k == 0 ? p.x : p.y; }
double coordinate(const Vec3& p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; }

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
Eigen::SparseMatrix<double> node_graph(const FeNodes<D>& n) {
  const std::vector<int>& first = n.first;
  const int nodes = static_cast<int>(n.unknowns) / D;
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

// The discrete problem: the mesh's quadratic nodes, each node's unknowns, the phases'
// materials, the quadrature and the loads — load j < N the unit macroscopic (engineering)
// strain j, load N (when thermal) the unit temperature change.
template <int D>
struct Problem {
  static constexpr std::size_t N = voigt_size(D);
  static constexpr int kDofs = D * Simplex<D>::kNodes;
  const ExportMesh<D>& m;
  FeNodes<D> nodes;
  Materials<D> mat;
  Quadrature<D> q;
  int loads = 0;

  Problem(const ExportMesh<D>& mesh, bool plane_stress, bool thermal)
      : m(mesh), nodes(fe_nodes(mesh)), mat(materials(mesh, plane_stress)), q(degree_two_rule<D>()),
        loads(static_cast<int>(N) + (thermal ? 1 : 0)) {}

  // The strain load j imposes on a phase: E_j, or minus its free thermal strain.
  VoigtVector<D> imposed(int phase, int j) const {
    if (j < static_cast<int>(N)) return VoigtVector<D>::Unit(j);
    return -mat.thermal_strain[static_cast<std::size_t>(phase)];
  }
  // The unknown of element c's local degree of freedom k (node k / D, component k % D);
  // -1 when held.
  int dof(std::size_t c, int k) const {
    const int base = nodes.first[static_cast<std::size_t>(nodes.element[c][static_cast<std::size_t>(k / D)])];
    return base < 0 ? -1 : base + k % D;
  }
};

// The stiffness matrix's lower triangle with its pattern made first, from the node graph
// (each node pair's D x D block, the diagonal blocks' lower half), its entries zero.
template <int D>
Eigen::SparseMatrix<double> stiffness_pattern(const Problem<D>& p) {
  const Eigen::SparseMatrix<double> graph = node_graph(p.nodes);
  const auto n = static_cast<Eigen::Index>(p.nodes.unknowns);
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
  const std::string key = o.reference ? "homogenise.reference" : "homogenise.solver";
  if (need > have)
    throw ConfigError(key + " = fe: the finite elements on this mesh (" + std::to_string(unknowns) +
                      " unknowns) need about " + size(need) + ", more than the " + size(have) + " available: set " +
                      key + (o.reference ? " = none" : " = openfoam") + ", or mesh coarser or fewer grains");
}

template <int D>
FeHomogenised<voigt_size(D)> homogenise(const ExportMesh<D>& m, bool plane_stress, bool thermal, const FeOptions& o) {
  constexpr std::size_t N = voigt_size(D);
  const auto start = std::chrono::steady_clock::now();
  const Problem<D> p(m, plane_stress, thermal);
  const auto [k, f] = assemble(p);
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> solver;
  solver.cholmod().nmethods = 1;  // the unknowns are numbered in a fill-reducing order (fe_nodes.hpp)
  solver.cholmod().method[0].ordering = CHOLMOD_NATURAL;
  solver.analyzePattern(k);
  check_memory(solver.cholmod(), k, p.loads, p.nodes.unknowns, o);
  solver.factorize(k);
  if (solver.info() != Eigen::Success)
    throw GeometryError("finite-element reference: the stiffness matrix is not positive definite (a phase without "
                        "stiffness, or a mesh the periodic ties do not hold)");
  const Eigen::MatrixXd u = solver.solve(f);
  const Eigen::MatrixXd mean = mean_stresses(p, u);
  FeHomogenised<N> out;
  out.unknowns = p.nodes.unknowns;
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
