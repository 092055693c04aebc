// Laminates: the exact answers the homogenisation tests hold grainmesh to, and the
// periodic cell of strips that builds one from grains.
#pragma once

#include <array>
#include <cstdio>
#include <string>

namespace grainmesh::test {

struct Material {
  double E, nu;
  double alpha = 0.0;  // 1/K
  double mu() const { return E / (2 * (1 + nu)); }
  double lambda() const { return E * nu / ((1 + nu) * (1 - 2 * nu)); }  // plane strain
  double M() const { return lambda() + 2 * mu(); }
  double three_K() const { return E / (1 - 2 * nu); }  // plane strain: 3 lambda + 2 mu
};

// The exact plane-strain stiffness of a laminate with layers normal to x, `soft` of the
// area soft: C11, C22, C12, C66.
inline std::array<double, 4> laminate(const Material& hard, const Material& soft, double f) {
  auto mean = [&](auto g) { return (1 - f) * g(hard) + f * g(soft); };
  const double inv_M = mean([](const Material& m) { return 1 / m.M(); });
  const double l_M = mean([](const Material& m) { return m.lambda() / m.M(); });
  return {1 / inv_M, mean([](const Material& m) { return m.M() - m.lambda() * m.lambda() / m.M(); }) + l_M * l_M / inv_M,
          l_M / inv_M, 1 / mean([](const Material& m) { return 1 / m.mu(); })};
}

// The exact stiffness of a 3D laminate of two isotropic phases with layers normal to x,
// `soft` of the volume soft (Backus): C11 = 1/<1/M>, C12 = C13 = <l/M>/<1/M>, C22 = C33 =
// <M - l^2/M> + <l/M>^2/<1/M>, C23 = <l - l^2/M> + <l/M>^2/<1/M>, C44 = <mu> (shear in the
// layers), C55 = C66 = 1/<1/mu> (across them); M = l + 2 mu. Voigt order xx yy zz yz xz xy.
inline std::array<std::array<double, 6>, 6> laminate_3d(const Material& hard, const Material& soft, double f) {
  auto mean = [&](auto g) { return (1 - f) * g(hard) + f * g(soft); };
  const double inv_M = mean([](const Material& m) { return 1 / m.M(); });
  const double l_M = mean([](const Material& m) { return m.lambda() / m.M(); });
  const double C11 = 1 / inv_M, C12 = l_M / inv_M;
  const double C22 = mean([](const Material& m) { return m.M() - m.lambda() * m.lambda() / m.M(); }) + l_M * l_M / inv_M;
  const double C23 = mean([](const Material& m) { return m.lambda() - m.lambda() * m.lambda() / m.M(); }) + l_M * l_M / inv_M;
  const double C44 = mean([](const Material& m) { return m.mu(); });
  const double C55 = 1 / mean([](const Material& m) { return 1 / m.mu(); });
  return {{{C11, C12, C12, 0, 0, 0}, {C12, C22, C23, 0, 0, 0}, {C12, C23, C22, 0, 0, 0},
           {0, 0, 0, C44, 0, 0}, {0, 0, 0, 0, C55, 0}, {0, 0, 0, 0, 0, C55}}};
}

// A periodic cell of ten strips (seeds in a row: layers normal to x; in a column: normal
// to y), three of them soft; each phase's alpha when it has one.
// The mesh is refined along the grain boundaries (`boundary_size`): solidDisplacementFoam's
// error lives in the cells next to a phase interface (README, Homogenisation).
inline std::string laminate_config(const Material& hard, const Material& soft, bool normal_to_x, double boundary_size) {
  auto phase = [](const Material& m) {
    char alpha[32];
    std::snprintf(alpha, sizeof alpha, "%.17g", m.alpha);
    return "E = " + std::to_string(m.E) + "\nnu = " + std::to_string(m.nu) + "\n" +
           (m.alpha != 0.0 ? "alpha = " + std::string(alpha) + "\n" : "");
  };
  std::string seeds;
  for (int i = 0; i < 10; ++i) {
    const double along = (i + 0.5) / 10.0;
    seeds += (i ? ", " : "") + (normal_to_x ? std::to_string(2 * along) + " 0.5" : "0.5 " + std::to_string(2 * along));
  }
  return "[domain]\nwidth = " + std::string(normal_to_x ? "2" : "1") + "\nheight = " + (normal_to_x ? "1" : "2") +
         "\nperiodic = true\n[tessellation]\nseeds = " + seeds + "\nphase_mode = grain\n[phase.hard]\nfraction = rest\n" +
         phase(hard) + "[phase.soft]\nfraction = 0.3\n" + phase(soft) + "[mesh]\nboundary_size = " +
         std::to_string(boundary_size) + "\n";
}

}  // namespace grainmesh::test
