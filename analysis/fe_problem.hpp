// The quadratic finite elements' element-level parts: the quadrature, each element's
// geometry and strain matrices, the phases' materials and the discrete problem. Private to
// the finite-element solve (Eigen's types; included by fe_homogenise.cpp only).
#pragma once

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "analysis/bounds.hpp"
#include "analysis/fe_nodes.hpp"
#include "analysis/voigt.hpp"
#include "common/errors.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_material.hpp"

namespace grainmesh::fe_detail {

inline double coordinate(const Vec2& p, int k) { return k == 0 ? p.x : p.y; }
inline double coordinate(const Vec3& p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; }

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

// Point i of `points` as a vector.
template <int D, class Points>
Eigen::Matrix<double, D, 1> point_at(const Points& points, int i) {
  Eigen::Matrix<double, D, 1> x;
  for (int r = 0; r < D; ++r) x(r) = coordinate(points[static_cast<std::size_t>(i)], r);
  return x;
}

// Element c's Jacobian: column k is corner k + 1 less corner 0.
template <int D>
Eigen::Matrix<double, D, D> simplex_jacobian(const ExportMesh<D>& m, std::size_t c) {
  const auto corners = element_corners(m, c);
  const auto& points = mesh_points(m);
  Eigen::Matrix<double, D, D> jacobian;
  for (int k = 0; k < D; ++k)
    jacobian.col(k) = point_at<D>(points, corners[static_cast<std::size_t>(k + 1)]) - point_at<D>(points, corners[0]);
  return jacobian;
}

template <int D>
ElementGeometry<D> element_geometry(const ExportMesh<D>& m, std::size_t c, const Quadrature<D>& q) {
  const Eigen::Matrix<double, D, D> jacobian = simplex_jacobian(m, c);
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
  // A nested split of `coarse`'s mesh, its unknowns numbered after the coarse level's
  // (fe_nodes.hpp), the same phases and loads.
  Problem(const ExportMesh<D>& mesh, const Problem& coarse)
      : m(mesh), nodes(fe_nodes(mesh, coarse.m, coarse.nodes)), mat(coarse.mat), q(coarse.q), loads(coarse.loads) {}

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

}  // namespace grainmesh::fe_detail
