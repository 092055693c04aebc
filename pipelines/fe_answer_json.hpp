// How report.json writes what the finite elements add to a periodic answer (analysis/
// answer.hpp): their error estimate, their solve, the reference beside OpenFOAM's answer
// and OpenFOAM's answer beside theirs, each with the errors against the other (Voigt size
// N = 3 or 6; docs/report.md).
#pragma once

#include <cstddef>

#include "analysis/answer.hpp"
#include "pipelines/report.hpp"

namespace grainmesh {

// error_estimate: {stiffness {Cij}, bulk_modulus, shear_modulus, thermal_expansion when
// heated, basis}, each relative.
template <std::size_t N>
Json error_estimate_json(const ErrorEstimate<N>& x);

// The finite elements' solve: {method, unknowns, seconds (both levels'), iterations (the
// fine level's conjugate gradients; 0 when factorised), coarse {unknowns, seconds}}.
template <std::size_t N>
Json fe_solve_json(const FeLevels<N>& l);

// The finite-element reference into `e`: reference {stiffness, bulk_modulus,
// shear_modulus, thermal_expansion when heated, error_estimate, and its solve} and the
// answer's discretisation_error against it.
template <std::size_t N>
void add_reference(const ReferenceAnswer<N>& r, Json& e);

// OpenFOAM's answer beside the finite elements' (solver fe, solved): {stiffness,
// symmetry_error, bulk_modulus, shear_modulus, engineering, thermal_expansion when heated,
// discretisation_error against the answer}.
template <std::size_t N>
Json openfoam_json(const PeriodicAnswer<N>& o);

}  // namespace grainmesh
