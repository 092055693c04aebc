// Eigen and CHOLMOD are included here (fe_homogenise.hpp shows our own types; the factors
// and the coarse level in the private fe_coarse_level.hpp).
#include "analysis/fe_homogenise.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <tuple>
#include <string>
#include <vector>

#include "analysis/blas_threads.hpp"
#include "analysis/bounds.hpp"
#include "analysis/fe_coarse_level.hpp"
#include "analysis/fe_nodes.hpp"
#include "analysis/fe_problem.hpp"
#include "analysis/fe_two_grid.hpp"
#include "common/errors.hpp"
#include "common/side_by_side.hpp"

namespace grainmesh {

namespace {

using namespace fe_detail;

// The stiffness matrix's lower triangle with its pattern made first, from the node graph
// `graph` (each node pair's D x D block, the diagonal blocks' lower half), its entries
// zero. Column (j, d) holds node j's rows d .. D - 1, then D rows for each node of the
// graph's column j after j, in its order: entry (i, c) of it lies D e - d + c past the
// column's start, e the rank of node i in the graph's column (node_rank).
template <int D>
void stiffness_pattern(const Problem<D>& p, const NodeGraph& graph, Eigen::SparseMatrix<double>& k) {
  const auto n = static_cast<Eigen::Index>(p.nodes.unknowns);
  k.resize(n, n);
  k.resizeNonZeros(static_cast<Eigen::Index>(D * D * graph.inner.size()));  // an upper bound, trimmed below
  int* outer = k.outerIndexPtr();
  int* inner = k.innerIndexPtr();
  int next = 0;
  for (std::size_t j = 0; j + 1 < graph.outer.size(); ++j)
    for (int cj = 0; cj < D; ++cj) {
      const int column = D * static_cast<int>(j) + cj;
      outer[column] = next;
      for (int e = graph.outer[j]; e < graph.outer[j + 1]; ++e)
        for (int ci = 0; ci < D; ++ci)
          if (const int row = D * graph.inner[static_cast<std::size_t>(e)] + ci; row >= column) inner[next++] = row;
    }
  outer[n] = next;
  k.resizeNonZeros(next);
  std::fill(k.valuePtr(), k.valuePtr() + next, 0.0);
}

// The rank of node i in the graph's column j (i >= j, the two sharing an element): entry
// (D i + c, D j + d) of the stiffness pattern lies at D rank - d + c past column D j + d's
// start (stiffness_pattern). One search per pair of an element's nodes, not one per entry.
int node_rank(const NodeGraph& graph, int i, int j) {
  const int* begin = graph.inner.data() + graph.outer[static_cast<std::size_t>(j)];
  const int* end = graph.inner.data() + graph.outer[static_cast<std::size_t>(j) + 1];
  return static_cast<int>(std::lower_bound(begin, end, i) - begin);
}

// The stiffness matrix `k` (its lower triangle) and each load's right-hand side `f`: each
// element's entries added in place into the pattern. Made in the caller's matrix: Eigen
// 3.4's sparse matrices have no move, and a copy of the 1,000-grain 3D cell's fine level
// (2.3 GB) took seconds.
template <int D>
void assemble(const Problem<D>& p, Eigen::SparseMatrix<double>& k, Eigen::MatrixXd& f) {
  constexpr int kDofs = Problem<D>::kDofs;
  constexpr int kNodes = Simplex<D>::kNodes;
  const NodeGraph graph = node_graph(p.nodes);
  stiffness_pattern(p, graph, k);
  const int* outer = k.outerIndexPtr();
  double* value = k.valuePtr();
  f.setZero(k.rows(), p.loads);
  Eigen::Matrix<double, kDofs, Eigen::Dynamic> fe(kDofs, p.loads);
  for (std::size_t c = 0; c < element_count(p.m); ++c) {
    const ElementGeometry<D> g = element_geometry(p.m, c, p.q);
    const int phase = p.m.phase[c];
    Eigen::Matrix<double, kDofs, kDofs> ke = Eigen::Matrix<double, kDofs, kDofs>::Zero();
    fe.setZero();
    for (std::size_t i = 0; i < p.q.weights.size(); ++i) {
      const Eigen::Matrix<double, kDofs, static_cast<int>(Problem<D>::N)> btc =
          p.q.weights[i] * g.measure * g.b[i].transpose() * p.mat.stiffness[static_cast<std::size_t>(phase)];
      ke.noalias() += btc * g.b[i];
      for (int j = 0; j < p.loads; ++j) fe.col(j).noalias() -= btc * p.imposed(phase, j);
    }
    std::array<int, kNodes> node;  // each local node's unknown node (first / D), -1 held
    for (int a = 0; a < kNodes; ++a) {
      const int first = p.nodes.first[static_cast<std::size_t>(p.nodes.element[c][static_cast<std::size_t>(a)])];
      node[static_cast<std::size_t>(a)] = first < 0 ? -1 : first / D;
    }
    for (int a = 0; a < kNodes; ++a) {
      const int i = node[static_cast<std::size_t>(a)];
      if (i < 0) continue;
      for (int ci = 0; ci < D; ++ci) f.row(D * i + ci) += fe.row(D * a + ci);
      for (int b = 0; b < kNodes; ++b) {
        const int j = node[static_cast<std::size_t>(b)];
        if (j < 0 || j > i) continue;
        const int rank = node_rank(graph, i, j);
        for (int cj = 0; cj < D; ++cj) {
          double* column = value + outer[D * j + cj] + D * rank - cj;
          for (int ci = i == j ? cj : 0; ci < D; ++ci) column[ci] += ke(D * a + ci, D * b + cj);
        }
      }
    }
  }
}

// Each load's volume-averaged stress (a column each) from the solved fluctuations `u`.
// The stiffness of p's linear elements, its lower triangle, in linear_columns' numbering
// `column` (fe_coarse_level.hpp): each element's strain matrix that of the quadratic
// element times its prolongation (a corner's value its own, a midside node's its edge's
// ends' mean), integrated by the same rule. It is P^T K P to rounding (within 4.6e-16 of
// the largest entry on the 100- and 1,000-grain 3D cells; checked on small levels,
// fe_coarse_level.cpp), without the product, which with its symmetric copy took 3.1 s of
// the 1,000-grain 3D cell's coarse level.
template <int D>
Eigen::SparseMatrix<double> linear_stiffness(const Problem<D>& p, const std::vector<int>& column) {
  constexpr int kCorners = D + 1;
  constexpr int kDofs = D * kCorners;
  constexpr auto edges = Simplex<D>::edges();
  const auto corners = static_cast<Eigen::Index>(std::count_if(column.begin(), column.end(), [](int c) { return c >= 0; }));
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(element_count(p.m) * static_cast<std::size_t>(kDofs * (kDofs + 1) / 2));
  for (std::size_t c = 0; c < element_count(p.m); ++c) {
    const ElementGeometry<D> g = element_geometry(p.m, c, p.q);
    const auto& stiffness = p.mat.stiffness[static_cast<std::size_t>(p.m.phase[c])];
    Eigen::Matrix<double, kDofs, kDofs> ke = Eigen::Matrix<double, kDofs, kDofs>::Zero();
    for (std::size_t i = 0; i < p.q.weights.size(); ++i) {
      Eigen::Matrix<double, static_cast<int>(Problem<D>::N), kDofs> b = g.b[i].template leftCols<kDofs>();
      for (std::size_t e = 0; e < edges.size(); ++e)
        for (const int end : edges[e])
          b.template middleCols<D>(D * end) += 0.5 * g.b[i].template middleCols<D>(D * (kCorners + static_cast<int>(e)));
      ke.noalias() += (p.q.weights[i] * g.measure) * b.transpose() * stiffness * b;
    }
    std::array<int, kCorners> at{};  // each corner's first linear unknown, -1 held
    for (int a = 0; a < kCorners; ++a) {
      const int r = p.nodes.first[static_cast<std::size_t>(p.nodes.element[c][static_cast<std::size_t>(a)])];
      at[static_cast<std::size_t>(a)] = r < 0 ? -1 : D * column[static_cast<std::size_t>(r / D)];
    }
    for (int a = 0; a < kCorners; ++a)
      for (int b = 0; b < kCorners; ++b) {
        if (at[static_cast<std::size_t>(a)] < 0 || at[static_cast<std::size_t>(b)] < 0) continue;
        for (int ci = 0; ci < D; ++ci)
          for (int cj = 0; cj < D; ++cj)
            if (const int row = at[static_cast<std::size_t>(a)] + ci, col = at[static_cast<std::size_t>(b)] + cj; row >= col)
              entries.emplace_back(row, col, ke(D * a + ci, D * b + cj));
      }
  }
  Eigen::SparseMatrix<double> out(D * corners, D * corners);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

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

template <int D>
std::unique_ptr<Factor> factorise(const Eigen::SparseMatrix<double>& k, const Problem<D>& p, const FeOptions& o) {
  return factorise(analyse(k), k, p.loads, o);
}

// The effective stiffness (and expansion, when thermal) from the solved fluctuations `u`.
template <int D>
FeHomogenised<voigt_size(D)> effective(const Problem<D>& p, const Eigen::MatrixXd& u, bool thermal) {
  constexpr std::size_t N = voigt_size(D);
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
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <int D>
FeHomogenised<voigt_size(D)> homogenise(const ExportMesh<D>& m, bool plane_stress, bool thermal, const FeOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const Problem<D> p(m, plane_stress, thermal);
  Eigen::SparseMatrix<double> k;
  Eigen::MatrixXd f;
  assemble(p, k, f);
  const Eigen::MatrixXd u = factorise(k, p, o)->solve(f);
  FeHomogenised<voigt_size(D)> out = effective(p, u, thermal);
  out.seconds = seconds_since(start);
  return out;
}

// The prolongation from the coarse level's unknowns to the fine's: the coarse quadratic
// shape functions at each fine node (fine element 2^D c + k lies in coarse element c).
template <int D>
Eigen::SparseMatrix<double> prolongation(const Problem<D>& coarse, const Problem<D>& fine) {
  using Point = Eigen::Matrix<double, D, 1>;
  auto at = [](const auto& points, int i) { return point_at<D>(points, i); };
  constexpr auto edges = Simplex<D>::edges();
  const auto& cp = mesh_points(coarse.m);
  const auto& fp = mesh_points(fine.m);
  std::vector<char> done(fine.nodes.unknowns / D, 0);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(fine.nodes.unknowns * 4);
  for (std::size_t c = 0; c < element_count(fine.m); ++c) {
    const std::size_t e = c >> D;
    const auto corners = element_corners(coarse.m, e);
    const Eigen::Matrix<double, D, D> inverse = simplex_jacobian(coarse.m, e).inverse();
    const auto fc = element_corners(fine.m, c);
    for (int a = 0; a < Simplex<D>::kNodes; ++a) {
      const int r = fine.nodes.first[static_cast<std::size_t>(fine.nodes.element[c][static_cast<std::size_t>(a)])];
      if (r < 0 || done[static_cast<std::size_t>(r / D)]) continue;
      done[static_cast<std::size_t>(r / D)] = 1;
      const Point x = a <= D ? at(fp, fc[static_cast<std::size_t>(a)])
                             : 0.5 * (at(fp, fc[static_cast<std::size_t>(edges[static_cast<std::size_t>(a - D - 1)][0])]) +
                                      at(fp, fc[static_cast<std::size_t>(edges[static_cast<std::size_t>(a - D - 1)][1])]));
      const Point tail = inverse * (x - at(cp, corners[0]));
      std::array<double, D + 1> l;
      l[0] = 1.0 - tail.sum();
      for (int k = 0; k < D; ++k) l[static_cast<std::size_t>(k + 1)] = tail(k);
      for (int b = 0; b < Simplex<D>::kNodes; ++b) {
        const int s = coarse.nodes.first[static_cast<std::size_t>(coarse.nodes.element[e][static_cast<std::size_t>(b)])];
        const double phi = b <= D ? l[static_cast<std::size_t>(b)] * (2.0 * l[static_cast<std::size_t>(b)] - 1.0)
                                  : 4.0 * l[static_cast<std::size_t>(edges[static_cast<std::size_t>(b - D - 1)][0])] *
                                        l[static_cast<std::size_t>(edges[static_cast<std::size_t>(b - D - 1)][1])];
        if (s < 0 || std::abs(phi) < 1e-12) continue;
        for (int d = 0; d < D; ++d) entries.emplace_back(r + d, s + d, phi);
      }
    }
  }
  Eigen::SparseMatrix<double> out(static_cast<Eigen::Index>(fine.nodes.unknowns),
                                  static_cast<Eigen::Index>(coarse.nodes.unknowns));
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

// The levels' conjugate gradients: each load's residual to 1e-4 of its norm, in at most
// 200 cycles; beyond, the level is factorised. The effective stiffness and expansion are
// far more precise than the residual: on the 3D example, stopped at 1e-3, 1e-4 and 1e-5,
// they lie within 8e-8, 9e-9 and 1.3e-9 of the answer at 1e-6 (relative to the largest
// entry), five orders below the finite elements' own error estimate (0.4 %), in 10, 15
// and 20 fine cycles against 24 (the 1,000-grain 2D cell at 1e-6, 1e-8 and 1e-10: within
// 2e-11 of C11).
constexpr double kTwoGridTolerance = 1e-4;
std::atomic<int> two_grid_threads{0};  // limit_fe_threads's; 0: every core
constexpr int kTwoGridIterations = 200;

template <int D>
FeNested<voigt_size(D)> homogenise_nested(const ExportMesh<D>& coarse, const ExportMesh<D>& fine, bool plane_stress,
                                          bool thermal, const FeOptions& o) {
  if (element_count(fine) != (element_count(coarse) << D))
    throw GeometryError("finite-element levels: the fine mesh has " + std::to_string(element_count(fine)) +
                        " elements, not the coarse mesh's split (" + std::to_string(element_count(coarse) << D) + ")");
  FeNested<voigt_size(D)> out;
  const auto start = std::chrono::steady_clock::now();
  const Problem<D> pc(coarse, plane_stress, thermal);
  Eigen::SparseMatrix<double> kc;
  Eigen::MatrixXd fc;
  assemble(pc, kc, fc);
  const int threads = two_grid_threads > 0 ? two_grid_threads.load() : cores();
  // The coarse level solved (factorised, or by its cycles: CoarseLevel) beside the fine
  // level's assembly, which needs only the coarse level's nodes (the 1,000-grain 2D cell:
  // 0.7 s each; the 3D one 14 s and 8 s); each on one thread.
  std::optional<BlasThreads> one_blas_thread(std::in_place, 1);
  std::optional<CoarseLevel> level;
  Eigen::MatrixXd uc;
  std::optional<Problem<D>> pf;
  Eigen::SparseMatrix<double> kf, pr;
  Eigen::MatrixXd ff;
  auto coarse_done = start;
  side_by_side({0, 1}, threads, [&](int job) {
    if (job == 0) {
      level.emplace(kc, pc.nodes, [&](const std::vector<int>& columns) { return linear_stiffness(pc, columns); },
                    pc.loads, o);
      uc = level->solve(fc, kTwoGridTolerance, kTwoGridIterations);
      out.coarse = effective(pc, uc, thermal);
      out.coarse.iterations = level->iterations();
      coarse_done = std::chrono::steady_clock::now();
    } else {
      pf.emplace(fine, pc);
      assemble(*pf, kf, ff);
      pr = prolongation(pc, *pf);
    }
  });
  // Wall times: the coarse level's to its answer, the fine level's from there (its
  // assembly, beside the coarse level's solve, in neither), so that their sum is the whole.
  out.coarse.seconds = std::chrono::duration<double>(coarse_done - start).count();
  const TwoGridSolve s = two_grid_solve(
      kf, ff, pr, [&](const Eigen::MatrixXd& r) { return level->cycle(r); }, pr * uc,
      kTwoGridTolerance, kTwoGridIterations, threads);
  one_blas_thread.reset();  // the fine level's factor, where the cycles fail, on every core
  const Eigen::MatrixXd uf = s.converged ? s.u : factorise(kf, *pf, o)->solve(ff);
  out.fine = effective(*pf, uf, thermal);
  out.fine.iterations = s.converged ? s.iterations : 0;
  out.fine.seconds = seconds_since(coarse_done);
  return out;
}

}  // namespace

FeHomogenised<3> fe_homogenise(const ExportMesh<2>& m, bool plane_stress, bool thermal, const FeOptions& o) {
  return homogenise(m, plane_stress, thermal, o);
}

FeHomogenised<6> fe_homogenise(const ExportMesh<3>& m, bool thermal, const FeOptions& o) {
  return homogenise(m, false, thermal, o);
}

void limit_fe_threads(int threads) {
  two_grid_threads = threads;
  set_blas_threads(threads);
}

FeNested<3> fe_homogenise_nested(const ExportMesh<2>& coarse, const ExportMesh<2>& fine, bool plane_stress,
                                 bool thermal, const FeOptions& o) {
  return homogenise_nested(coarse, fine, plane_stress, thermal, o);
}

FeNested<6> fe_homogenise_nested(const ExportMesh<3>& coarse, const ExportMesh<3>& fine, bool thermal,
                                 const FeOptions& o) {
  return homogenise_nested(coarse, fine, false, thermal, o);
}

}  // namespace grainmesh
