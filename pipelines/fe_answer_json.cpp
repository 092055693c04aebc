#include "pipelines/fe_answer_json.hpp"

#include "pipelines/tensor_json.hpp"

namespace grainmesh {

namespace {

// The finite elements' method, as report.json names it.
template <std::size_t N>
const char* fe_method() {
  return N == 3 ? "finite elements: 6-node triangles, periodic" : "finite elements: 10-node tetrahedra, periodic";
}

// An answer's relative errors against the finite elements: {stiffness {Cij},
// bulk_modulus, shear_modulus, thermal_expansion when heated} (ReferenceAnswer).
template <std::size_t N>
Json discretisation_error_json(const ReferenceAnswer<N>& r) {
  Json error{{"stiffness", stiffness_json<N>(r.stiffness_error)},
             {"bulk_modulus", r.bulk_error},
             {"shear_modulus", r.shear_error}};
  if (r.expansion_error) error["thermal_expansion"] = voigt_json<N>(*r.expansion_error);
  return error;
}

}  // namespace

template <std::size_t N>
Json error_estimate_json(const ErrorEstimate<N>& x) {
  Json e{{"stiffness", stiffness_json<N>(x.stiffness)}, {"bulk_modulus", x.bulk_modulus}, {"shear_modulus", x.shear_modulus}};
  if (x.expansion) e["thermal_expansion"] = voigt_json<N>(*x.expansion);
  e["basis"] = x.basis;
  return e;
}

template <std::size_t N>
Json fe_solve_json(const FeLevels<N>& l) {
  return {{"method", fe_method<N>()},
          {"unknowns", l.fine.unknowns},
          {"seconds", l.seconds()},
          {"iterations", l.fine.iterations},
          {"coarse", {{"unknowns", l.coarse.unknowns}, {"seconds", l.coarse.seconds}, {"iterations", l.coarse.iterations}}}};
}

template <std::size_t N>
void add_reference(const ReferenceAnswer<N>& r, Json& e) {
  Json ref{{"stiffness", stiffness_json<N>(r.stiffness)},
           {"bulk_modulus", r.bulk_modulus},
           {"shear_modulus", r.shear_modulus}};
  if (r.fe.fine.expansion) ref["thermal_expansion"] = voigt_json<N>(*r.fe.fine.expansion);
  ref["error_estimate"] = error_estimate_json(r.fe.estimate);
  ref.update(fe_solve_json(r.fe));
  e["reference"] = ref;
  e["discretisation_error"] = discretisation_error_json(r);
}

template <std::size_t N>
Json openfoam_json(const PeriodicAnswer<N>& o) {
  Json j{{"stiffness", stiffness_json<N>(o.verdict.stiffness)},
         {"symmetry_error", o.verdict.symmetry_error},
         {"bulk_modulus", o.verdict.bulk_modulus},
         {"shear_modulus", o.verdict.shear_modulus}};
  Json& engineering = j["engineering"] = Json::object();
  for (const EngineeringConstants::Named& n : o.engineering.constants) engineering[n.name] = n.value;
  if (o.thermal) j["thermal_expansion"] = voigt_json<N>(o.thermal->expansion);
  if (o.reference) j["discretisation_error"] = discretisation_error_json(*o.reference);
  return j;
}

template Json error_estimate_json(const ErrorEstimate<3>&);
template Json error_estimate_json(const ErrorEstimate<6>&);
template Json fe_solve_json(const FeLevels<3>&);
template Json fe_solve_json(const FeLevels<6>&);
template void add_reference(const ReferenceAnswer<3>&, Json&);
template void add_reference(const ReferenceAnswer<6>&, Json&);
template Json openfoam_json(const PeriodicAnswer<3>&);
template Json openfoam_json(const PeriodicAnswer<6>&);

}  // namespace grainmesh
