#include "pipelines/report_json.hpp"

#include <type_traits>

#include "pipelines/fe_answer_json.hpp"
#include "pipelines/tensor_json.hpp"

namespace grainmesh {

namespace {

// A solve: corrections, residuals, the linear solver, the result's time directory
// (relative to `dir`), OpenFOAM's steps' seconds.
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

// A distribution: mean, std, p50, p90, p99, max.
Json distribution_json(const Distribution& d) {
  return {{"mean", d.mean}, {"std", d.std}, {"p50", d.p50}, {"p90", d.p90}, {"p99", d.p99}, {"max", d.max}};
}

// The mixed load: boundary, modulus, sigma_xx, strain_xx, its solve, volume_average
// {modulus, sigma_xx, ... (each Voigt component)}; with bounds voigt, reuss,
// hashin_shtrikman {lower, upper}, inside_bounds {voigt_reuss, hashin_shtrikman}.
template <std::size_t N>
Json mixed_json(const MixedAnswer<N>& a, const std::filesystem::path& dir) {
  Json e{{"boundary", "mixed"}, {"modulus", a.modulus}, {"sigma_xx", a.sigma_xx}, {"strain_xx", a.strain_xx}};
  e.update(solve_json(a.run, dir));
  Json average{{"modulus", a.volume_average_modulus}};
  for (std::size_t k = 0; k < N; ++k) average[std::string("sigma_") + voigt_names<N>()[k]] = a.volume_average[k];
  e["volume_average"] = average;
  if (!a.bounds) return e;
  e["voigt"] = a.bounds->voigt;
  e["reuss"] = a.bounds->reuss;
  if (a.bounds->hs_lower) e["hashin_shtrikman"] = {{"lower", *a.bounds->hs_lower}, {"upper", *a.bounds->hs_upper}};
  e["inside_bounds"]["voigt_reuss"] = a.verdict->inside_voigt_reuss;
  if (a.verdict->inside_hashin_shtrikman) e["inside_bounds"]["hashin_shtrikman"] = *a.verdict->inside_hashin_shtrikman;
  return e;
}

// The thermal expansion: thermal_expansion {xx ...} and thermal {delta_T, plane_state (2D),
// levin, levin_difference}.
template <std::size_t N>
void add_thermal(const ThermalAnswer<N>& t, Json& e) {
  e["thermal_expansion"] = voigt_json<N>(t.expansion);
  Json thermal{{"delta_T", t.delta_T}};
  if (!t.plane_state.empty()) thermal["plane_state"] = t.plane_state;
  if (t.levin) {
    thermal["levin"] = voigt_json<N>(*t.levin);
    thermal["levin_difference"] = t.levin_difference;
  }
  e["thermal"] = thermal;
}

// The load cases as solved by OpenFOAM: load_cases [{name, strain, stress, delta_T when
// heated, then its solve}], corrections (the most any case took), volume_average
// {stiffness}.
template <std::size_t N>
void add_load_cases(const PeriodicAnswer<N>& a, const std::filesystem::path& dir, Json& e) {
  Json cases = Json::array();
  for (const SolvedLoadCase<N>& c : a.cases) {
    Json j{{"name", c.load.name}, {"strain", voigt_json<N>(c.load.strain)}, {"stress", voigt_json<N>(c.stress)}};
    if (c.load.delta_T != 0.0) j["delta_T"] = c.load.delta_T;
    j.update(solve_json(c.run, dir));
    cases.push_back(j);
  }
  e["load_cases"] = cases;
  e["corrections"] = a.corrections();
  e["volume_average"] = {{"stiffness", stiffness_json<N>(a.volume_average_stiffness)}};
}

// The periodic answer: boundary, solver, the judged stiffness (stiffness, symmetry_error,
// bulk_modulus, shear_modulus), volume_fractions, the bounds (voigt, reuss,
// hashin_shtrikman {bulk_lower, bulk_upper, shear_lower, shear_upper}), bounds_tolerance,
// inside_bounds, engineering, anisotropy, the thermal expansion, error_estimate; the
// finite elements' solve (solver fe: finite_elements {method, unknowns, seconds}); the
// OpenFOAM load cases when solved, OpenFOAM's answer beside the finite elements'
// (openfoam) or the reference beside OpenFOAM's with the errors against it.
template <std::size_t N>
Json periodic_json(const PeriodicAnswer<N>& a, const std::filesystem::path& dir) {
  const StiffnessVerdict<N>& v = a.verdict;
  const TensorBounds<N>& b = a.bounds;
  Json e{{"boundary", "periodic"},
         {"solver", a.solver == Solver::fe ? "fe" : "openfoam"},
         {"stiffness", stiffness_json<N>(v.stiffness)},
         {"symmetry_error", v.symmetry_error},
         {"bulk_modulus", v.bulk_modulus},
         {"shear_modulus", v.shear_modulus},
         {"volume_fractions", a.fractions},
         {"voigt", stiffness_json<N>(b.voigt)},
         {"reuss", stiffness_json<N>(b.reuss)}};
  if (b.bulk_upper)
    e["hashin_shtrikman"] = {{"bulk_lower", *b.bulk_lower},
                             {"bulk_upper", *b.bulk_upper},
                             {"shear_lower", *b.shear_lower},
                             {"shear_upper", *b.shear_upper}};
  e["bounds_tolerance"] = v.tolerance;
  e["inside_bounds"]["voigt_reuss"] = v.inside_voigt_reuss;
  if (v.inside_hashin_shtrikman) e["inside_bounds"]["hashin_shtrikman"] = *v.inside_hashin_shtrikman;
  Json& engineering = e["engineering"] = Json::object();
  for (const EngineeringConstants::Named& n : a.engineering.constants) engineering[n.name] = n.value;
  Json& anisotropy = e["anisotropy"] = {{"universal", a.engineering.universal_anisotropy}};
  if (a.engineering.normal_anisotropy) anisotropy["normal"] = *a.engineering.normal_anisotropy;
  if (a.engineering.shear_anisotropy) anisotropy["shear"] = *a.engineering.shear_anisotropy;
  if (a.thermal) add_thermal(*a.thermal, e);
  if (a.error_estimate) e["error_estimate"] = error_estimate_json(*a.error_estimate);
  if (a.fe) e["finite_elements"] = fe_solve_json(*a.fe);
  if (!a.cases.empty()) add_load_cases(a, dir, e);
  if (a.openfoam) e["openfoam"] = openfoam_json(*a.openfoam);
  if (a.reference) add_reference(*a.reference, e);
  return e;
}

// {PHASE: {volume_fraction, mean {xx, yy, zz, yz, xz, xy}, von_mises, max_principal,
// hydrostatic, partition (when loaded)}} of one state, the phases named `names`.
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

}  // namespace

template <std::size_t N>
Json effective_json(const Answer<N>& a, const std::filesystem::path& dir) {
  return std::visit(
      [&](const auto& e) {
        if constexpr (std::is_same_v<std::decay_t<decltype(e)>, MixedAnswer<N>>) return mixed_json(e, dir);
        else return periodic_json(e, dir);
      },
      a.effective);
}

template <std::size_t N>
Json stresses_json(const Answer<N>& a) {
  Json out = Json::object();
  for (const StateStresses& s : a.stresses) out[s.state] = phase_stresses_json(s.phases, a.phase_names);
  return out;
}

template Json effective_json(const Answer<3>&, const std::filesystem::path&);
template Json effective_json(const Answer<6>&, const std::filesystem::path&);
template Json stresses_json(const Answer<3>&);
template Json stresses_json(const Answer<6>&);

}  // namespace grainmesh
