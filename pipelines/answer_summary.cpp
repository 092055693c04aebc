#include "pipelines/answer_summary.hpp"

#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/format.hpp"

namespace grainmesh {

namespace {

// A modulus in GPa, to four digits as the report's Pa (the summary's unit: the report keeps Pa).
std::string gpa(double pa) { return to_text(pa / 1e9, 4); }

template <std::size_t N>
void print_mixed(const MixedAnswer<N>& a) {
  // 2D: the modulus in the plane state; 3D: under uniaxial strain (C11 of an isotropic cell).
  std::printf("  solved: %s %s GPa", N == 3 ? "effective modulus" : "modulus under uniaxial strain",
              gpa(a.modulus).c_str());
  if (a.bounds) std::printf(" (Reuss %s, Voigt %s)", gpa(a.bounds->reuss).c_str(), gpa(a.bounds->voigt).c_str());
  std::printf(", %d corrections\n", a.run.corrections);
}

// " (±x %)": a quantity's relative error estimate, when there is one.
std::string plus_minus(const std::optional<double>& estimate) {
  return estimate ? " (\u00b1" + to_text(100.0 * *estimate, 2) + " %)" : "";
}

// `stresses`: whether the phases' stresses were averaged (OpenFOAM's fields solved).
template <std::size_t N>
void print_periodic(const PeriodicAnswer<N>& a, bool stresses) {
  // The normal diagonal, C12 and the first shear's: all an isotropic cell has.
  constexpr std::size_t d = voigt_dimensions<N>();
  const Stiffness<N>& C = a.verdict.stiffness;
  std::vector<std::pair<std::size_t, std::size_t>> shown;
  for (std::size_t k = 0; k < d; ++k) shown.emplace_back(k, k);
  shown.emplace_back(0, 1);
  shown.emplace_back(d, d);
  const std::optional<ErrorEstimate<N>>& x = a.error_estimate;
  auto estimate = [&](auto of) { return x ? std::optional<double>(of(*x)) : std::nullopt; };
  std::string entries;
  for (const auto& ij : shown) {
    const std::size_t i = ij.first, j = ij.second;  // not a structured binding: captured below
    entries.append(entries.empty() ? "" : ", ")
        .append(stiffness_name<N>(i, j))
        .append(" ")
        .append(gpa(C[i][j]))
        .append(plus_minus(estimate([&](const ErrorEstimate<N>& e) { return e.stiffness[i][j]; })));
  }
  const std::string moduli =
      "K " + gpa(a.verdict.bulk_modulus) +
      plus_minus(estimate([](const ErrorEstimate<N>& e) { return e.bulk_modulus; })) +
      ", G " + gpa(a.verdict.shear_modulus) +
      plus_minus(estimate([](const ErrorEstimate<N>& e) { return e.shear_modulus; }));
  if (a.solver == Solver::fe)
    std::printf("  answer (finite elements, %zu unknowns, %.2f s): %s GPa; %s GPa\n", a.fe->fine.unknowns,
                a.fe->seconds(), entries.c_str(), moduli.c_str());
  else
    std::printf("  solved: %s GPa; %s GPa; symmetric to %.1e (%zu load cases, at most %d corrections)\n",
                entries.c_str(), moduli.c_str(), a.verdict.symmetry_error, a.cases.size(), a.corrections());
  if (!x) std::printf("  error estimate: not measured (homogenise.reference = fe measures it)\n");
  if (a.openfoam && a.openfoam->reference)
    std::printf("  OpenFOAM's load cases: K %s, G %s GPa, within %.2g %% of the answer (farthest: %s; "
                "effective.openfoam)\n",
                gpa(a.openfoam->verdict.bulk_modulus).c_str(), gpa(a.openfoam->verdict.shear_modulus).c_str(),
                100.0 * a.openfoam->reference->farthest_error, a.openfoam->reference->farthest.c_str());
  if (a.reference) {
    const ReferenceAnswer<N>& r = *a.reference;
    std::printf("  reference (finite elements, %zu unknowns, %.2f s): K %s, G %s GPa; the answer within %.2g %% of it "
                "(farthest: %s)\n",
                r.fe.fine.unknowns, r.fe.seconds(), gpa(r.bulk_modulus).c_str(), gpa(r.shear_modulus).c_str(),
                100.0 * r.farthest_error, r.farthest.c_str());
  }
  if (!a.thermal) return;
  const ThermalAnswer<N>& t = *a.thermal;
  std::string normals, names;
  const std::optional<std::array<double, N>> spread = x ? x->expansion : std::nullopt;
  for (std::size_t k = 0; k < d; ++k) {
    normals.append(k == 0 ? "" : ", ").append(to_text(t.expansion[k], 4));
    if (spread) normals.append(plus_minus((*spread)[k]));
    names.append(k == 0 ? "" : ", ").append(voigt_names<N>()[k]);
  }
  // In plane strain a 2D cell is held out of plane: its in-plane expansion is not a 3D one.
  const bool held = t.plane_state == "plane_strain";
  std::printf("  thermal%s: free %sexpansion %s 1/K (%s)%s%s\n",
              t.plane_state.empty() ? "" : (held ? " (plane strain)" : " (plane stress)"),
              t.plane_state.empty() ? "" : "in-plane ", normals.c_str(), names.c_str(),
              held ? " (held out of plane: not a 3D expansion, see docs/run.md)" : "",
              stresses ? "; residual stresses in report.json (stresses.thermal)" : "");
}

}  // namespace

template <std::size_t N>
void print_answer(const Answer<N>& a) {
  std::visit(
      [&](const auto& e) {
        if constexpr (std::is_same_v<std::decay_t<decltype(e)>, MixedAnswer<N>>) print_mixed(e);
        else print_periodic(e, !a.stresses.empty());
      },
      a.effective);
}

template void print_answer(const Answer<3>&);
template void print_answer(const Answer<6>&);

}  // namespace grainmesh
