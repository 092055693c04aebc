#include "pipelines/report_json.hpp"

#include <algorithm>

#include "common/format.hpp"

namespace grainmesh {

namespace {

// The Voigt index (1-based, as Cij names it) of component k: 1, 2, 6 in 2D.
template <std::size_t N>
char voigt_index(std::size_t k) {
  if constexpr (N == 3) return "126"[k];
  return static_cast<char>('1' + k);
}

}  // namespace

template <std::size_t N>
Json voigt_json(const std::array<double, N>& v) {
  Json out = Json::object();
  for (std::size_t k = 0; k < N; ++k) out[voigt_names<N>()[k]] = v[k];
  return out;
}

template <std::size_t N>
Json stiffness_json(const Stiffness<N>& c) {
  Json out = Json::object();
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i; j < N; ++j) out[std::string{'C', voigt_index<N>(i), voigt_index<N>(j)}] = c[i][j];
  return out;
}

Json solve_json(const SolveRun& r, const std::filesystem::path& dir) {
  Json json{{"corrections", r.corrections},
            {"final_residual", r.final_residual},
            {"stress_change", r.stress_change},
            {"component_residuals", r.component_residuals},
            {"linear_solver", r.linear_solver},
            {"result", std::filesystem::relative(r.result_dir, dir).string()},
            {"seconds",
             {{"decomposePar", r.decompose_seconds},
              {"solidDisplacementFoam", r.solver_seconds},
              {"reconstructPar", r.reconstruct_seconds}}}};
  if (!r.linear_solver_fallback.empty()) json["linear_solver_fallback"] = r.linear_solver_fallback;
  return json;
}

template <std::size_t N>
void add_load_cases(const PeriodicHomogenised<N>& h, const std::filesystem::path& dir, Json& effective) {
  Json cases = Json::array();
  int corrections = 0;
  for (const LoadCaseResult<N>& r : h.cases) {
    Json c{{"name", r.load.name}, {"strain", voigt_json<N>(r.load.strain)}, {"stress", voigt_json<N>(r.stress)}};
    if (r.load.delta_T != 0.0) c["delta_T"] = r.load.delta_T;
    c.update(solve_json(r.run, dir));
    cases.push_back(c);
    corrections = std::max(corrections, r.run.corrections);
  }
  effective["load_cases"] = cases;
  effective["corrections"] = corrections;
  effective["volume_average"] = {{"stiffness", stiffness_json<N>(symmetric_part(h.volume_average_stiffness))}};
}

template <std::size_t N>
void add_mixed(const MixedHomogenised<N>& h, const std::filesystem::path& dir, Json& effective) {
  effective["boundary"] = "mixed";
  effective["modulus"] = h.modulus;
  effective["sigma_xx"] = h.sigma_xx;
  effective["strain_xx"] = h.strain_xx;
  effective.update(solve_json(h.run, dir));
  Json average{{"modulus", h.volume_average_modulus}};
  for (std::size_t k = 0; k < N; ++k) average[std::string("sigma_") + voigt_names<N>()[k]] = h.volume_average[k];
  effective["volume_average"] = average;
}

template <std::size_t N>
Json state_stresses_json(const SolvedState<N>& s, const std::vector<double>& weight, const std::vector<int>& phase,
                         const std::vector<std::string>& names, int loaded, bool balanced) {
  const std::vector<StressTensor> own = cell_stress_tensors(s);
  const std::vector<StressTensor> virial = balanced ? cell_stress_tensors(s, true) : std::vector<StressTensor>{};
  const int component = loaded < 0 ? -1 : static_cast<int>(tensor_index<N>(static_cast<std::size_t>(loaded)));
  return phase_stresses_json(
      phase_stresses(own, weight, phase, static_cast<int>(names.size()), component, balanced ? &virial : nullptr),
      names);
}

Json distribution_json(const Distribution& d) {
  return {{"mean", d.mean}, {"std", d.std}, {"p50", d.p50}, {"p90", d.p90}, {"p99", d.p99}, {"max", d.max}};
}

Json phase_stresses_json(const std::vector<PhaseStresses>& phases, const std::vector<std::string>& names) {
  Json out = Json::object();
  for (std::size_t p = 0; p < phases.size(); ++p) {
    const PhaseStresses& s = phases[p];
    Json& j = out[names[p]];
    j = {{"volume_fraction", s.volume_fraction},
         {"mean", voigt_json<6>(s.mean)},
         {"von_mises", distribution_json(s.von_mises)},
         {"max_principal", distribution_json(s.max_principal)},
         {"hydrostatic", distribution_json(s.hydrostatic)}};
    if (s.partition) j["partition"] = *s.partition;
  }
  return out;
}

template <std::size_t N>
void add_stiffness(const StiffnessVerdict<N>& v, const TensorBounds<N>& b, const std::vector<double>& fractions,
                   Json& effective, std::vector<std::string>& warnings, const std::string& see, const std::string& why) {
  effective["stiffness"] = stiffness_json<N>(v.stiffness);
  effective["symmetry_error"] = v.symmetry_error;
  effective["bulk_modulus"] = v.bulk_modulus;
  effective["shear_modulus"] = v.shear_modulus;
  effective["volume_fractions"] = fractions;
  effective["voigt"] = stiffness_json<N>(b.voigt);
  effective["reuss"] = stiffness_json<N>(b.reuss);
  if (b.bulk_upper)
    effective["hashin_shtrikman"] = {{"bulk_lower", *b.bulk_lower},
                                     {"bulk_upper", *b.bulk_upper},
                                     {"shear_lower", *b.shear_lower},
                                     {"shear_upper", *b.shear_upper}};
  effective["bounds_tolerance"] = v.tolerance;
  effective["inside_bounds"]["voigt_reuss"] = v.inside_voigt_reuss;
  if (!v.inside_voigt_reuss)
    warnings.push_back("effective.stiffness does not lie between the Reuss and Voigt tensors (positive semidefinite "
                       "order): check the solve (" + see + ")");
  if (v.inside_hashin_shtrikman) effective["inside_bounds"]["hashin_shtrikman"] = *v.inside_hashin_shtrikman;
  for (const std::string& w : v.broken_hashin_shtrikman) warnings.push_back(w + " (" + why + ")");
}

void add_engineering(const EngineeringConstants& k, Json& effective) {
  Json& e = effective["engineering"] = Json::object();
  for (const EngineeringConstants::Named& n : k.constants) e[n.name] = n.value;
  Json& a = effective["anisotropy"] = {{"universal", k.universal_anisotropy}};
  if (k.normal_anisotropy) a["normal"] = *k.normal_anisotropy;
  if (k.shear_anisotropy) a["shear"] = *k.shear_anisotropy;
}

void add_modulus_verdict(const ModulusVerdict& v, Json& effective, std::vector<std::string>& warnings,
                         const std::string& why) {
  effective["inside_bounds"]["voigt_reuss"] = v.inside_voigt_reuss;
  if (v.inside_hashin_shtrikman) effective["inside_bounds"]["hashin_shtrikman"] = *v.inside_hashin_shtrikman;
  for (const std::string& w : v.broken) warnings.push_back(w + " (" + why + ")");
}

template <std::size_t N>
void add_levin(const std::array<double, N>& expansion, const std::array<double, N>& levin, Json& thermal,
               std::vector<std::string>& warnings, const std::string& advice) {
  const double d = levin_difference({expansion.begin(), expansion.end()}, {levin.begin(), levin.end()});
  thermal["levin"] = voigt_json<N>(levin);
  thermal["levin_difference"] = d;
  if (d > kLevinTolerance)
    warnings.push_back("effective.thermal_expansion differs from Levin's exact relation by " + to_text(100.0 * d, 2) +
                       " % of its largest component: " + advice);
}

template Json voigt_json<3>(const std::array<double, 3>&);
template Json voigt_json<6>(const std::array<double, 6>&);
template Json stiffness_json<3>(const Stiffness<3>&);
template Json stiffness_json<6>(const Stiffness<6>&);
template Json state_stresses_json(const SolvedState<3>&, const std::vector<double>&, const std::vector<int>&,
                                  const std::vector<std::string>&, int, bool);
template Json state_stresses_json(const SolvedState<6>&, const std::vector<double>&, const std::vector<int>&,
                                  const std::vector<std::string>&, int, bool);
template void add_load_cases(const PeriodicHomogenised<3>&, const std::filesystem::path&, Json&);
template void add_load_cases(const PeriodicHomogenised<6>&, const std::filesystem::path&, Json&);
template void add_mixed(const MixedHomogenised<3>&, const std::filesystem::path&, Json&);
template void add_mixed(const MixedHomogenised<6>&, const std::filesystem::path&, Json&);
template void add_stiffness<3>(const StiffnessVerdict<3>&, const TensorBounds<3>&, const std::vector<double>&, Json&,
                               std::vector<std::string>&, const std::string&, const std::string&);
template void add_stiffness<6>(const StiffnessVerdict<6>&, const TensorBounds<6>&, const std::vector<double>&, Json&,
                               std::vector<std::string>&, const std::string&, const std::string&);
template void add_levin<3>(const std::array<double, 3>&, const std::array<double, 3>&, Json&, std::vector<std::string>&,
                           const std::string&);
template void add_levin<6>(const std::array<double, 6>&, const std::array<double, 6>&, Json&, std::vector<std::string>&,
                           const std::string&);

}  // namespace grainmesh
