#include "pipelines/answer_summary.hpp"

#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/format.hpp"

namespace grainmesh {

namespace {

template <std::size_t N>
void print_mixed(const MixedAnswer<N>& a) {
  // 2D: the modulus in the plane state; 3D: under uniaxial strain (C11 of an isotropic cell).
  std::printf("  solved: %s %.4g Pa", N == 3 ? "effective modulus" : "modulus under uniaxial strain", a.modulus);
  if (a.bounds) std::printf(" (Reuss %.4g, Voigt %.4g)", a.bounds->reuss, a.bounds->voigt);
  std::printf(", %d corrections\n", a.run.corrections);
}

template <std::size_t N>
void print_periodic(const PeriodicAnswer<N>& a) {
  // The normal diagonal, C12 and the first shear's: all an isotropic cell has.
  constexpr std::size_t d = voigt_dimensions<N>();
  const Stiffness<N>& C = a.verdict.stiffness;
  std::vector<std::pair<std::size_t, std::size_t>> shown;
  for (std::size_t k = 0; k < d; ++k) shown.emplace_back(k, k);
  shown.emplace_back(0, 1);
  shown.emplace_back(d, d);
  std::string entries;
  for (const auto& [i, j] : shown)
    entries.append(entries.empty() ? "" : ", ").append(stiffness_name<N>(i, j)).append(" ").append(to_text(C[i][j], 4));
  std::printf("  solved: %s Pa; K %.4g, G %.4g Pa; symmetric to %.1e (%zu load cases, at most %d corrections)\n",
              entries.c_str(), a.verdict.bulk_modulus, a.verdict.shear_modulus, a.verdict.symmetry_error,
              a.cases.size(), a.corrections());
  if (a.reference) {
    const ReferenceAnswer<N>& r = *a.reference;
    std::printf("  reference (finite elements, %zu unknowns, %.2f s): K %.4g, G %.4g Pa; the answer within %.2g %% of it "
                "(farthest: %s)\n",
                r.fe.unknowns, r.fe.seconds, r.bulk_modulus, r.shear_modulus, 100.0 * r.farthest_error, r.farthest.c_str());
  }
  if (!a.thermal) return;
  const ThermalAnswer<N>& t = *a.thermal;
  std::string normals, names;
  for (std::size_t k = 0; k < d; ++k) {
    normals.append(k == 0 ? "" : ", ").append(to_text(t.expansion[k], 4));
    names.append(k == 0 ? "" : ", ").append(voigt_names<N>()[k]);
  }
  // In plane strain a 2D cell is held out of plane: its in-plane expansion is not a 3D one.
  const bool held = t.plane_state == "plane_strain";
  std::printf("  thermal%s: free %sexpansion %s 1/K (%s)%s; residual stresses in report.json (stresses.thermal)\n",
              t.plane_state.empty() ? "" : (held ? " (plane strain)" : " (plane stress)"),
              t.plane_state.empty() ? "" : "in-plane ", normals.c_str(), names.c_str(),
              held ? " (held out of plane: not a 3D expansion, see docs/run.md)" : "");
}

}  // namespace

template <std::size_t N>
void print_answer(const Answer<N>& a) {
  std::visit(
      [](const auto& e) {
        if constexpr (std::is_same_v<std::decay_t<decltype(e)>, MixedAnswer<N>>) print_mixed(e);
        else print_periodic(e);
      },
      a.effective);
}

template void print_answer(const Answer<3>&);
template void print_answer(const Answer<6>&);

}  // namespace grainmesh
