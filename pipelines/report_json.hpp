// How an answer is written into report.json, one writer for 2D and 3D (Voigt size N = 3
// or 6), so that both dimensions give the fields of docs/report.schema.json the same
// names and shapes: tensors by Voigt component, stiffnesses by Cij, load cases as an array.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/bounds.hpp"
#include "analysis/engineering.hpp"
#include "analysis/phase_statistics.hpp"
#include "analysis/solve.hpp"
#include "analysis/solved_state.hpp"
#include "analysis/verdicts.hpp"
#include "pipelines/report.hpp"

namespace grainmesh {

// {xx: .., yy: .., ...} of a tensor's Voigt components.
template <std::size_t N>
Json voigt_json(const std::array<double, N>& v);

// {C11: .., C12: .., ...}: the entries i <= j of a symmetric stiffness, named by their Voigt
// indices (1, 2, 6 in 2D; 1 to 6 in 3D), row by row.
template <std::size_t N>
Json stiffness_json(const Stiffness<N>& c);

// A solve: corrections, residuals, the linear solver, the result's time directory
// (relative to `dir`), OpenFOAM's steps' seconds.
Json solve_json(const SolveRun& r, const std::filesystem::path& dir);

// `stresses.CASE` of one solved state (phase_stresses_json): each cell weighted by
// `weight` (its area or volume) in its `phase` (indices into `names`); `loaded` the
// loaded component's index among the N Voigt components (a load case's), -1 none; with
// `balanced`, the means from the cells' virial stresses (a periodic case's).
template <std::size_t N>
Json state_stresses_json(const SolvedState<N>& s, const std::vector<double>& weight, const std::vector<int>& phase,
                         const std::vector<std::string>& names, int loaded, bool balanced);

// The solved periodic load cases in `effective`: load_cases [{name, strain, stress (Voigt
// components, Pa), delta_T when heated, then its solve}], corrections, the most any case
// took, and volume_average {stiffness}: the stiffness from the cells' volume averages.
template <std::size_t N>
void add_load_cases(const PeriodicHomogenised<N>& h, const std::filesystem::path& dir, Json& effective);

// The solved mixed load in `effective`: boundary, modulus, sigma_xx, strain_xx, its solve,
// and volume_average {modulus, sigma_xx, sigma_yy, ... (each Voigt component)}.
template <std::size_t N>
void add_mixed(const MixedHomogenised<N>& h, const std::filesystem::path& dir, Json& effective);

// A distribution: mean, std, p50, p90, p99, max.
Json distribution_json(const Distribution& d);

// {PHASE: {volume_fraction, mean {xx, yy, zz, yz, xz, xy}, von_mises, max_principal,
// hydrostatic, partition (when loaded)}} of one state, the phases named `names`.
Json phase_stresses_json(const std::vector<PhaseStresses>& phases, const std::vector<std::string>& names);

// A judged stiffness into `effective`: stiffness, symmetry_error, bulk_modulus,
// shear_modulus, volume_fractions, voigt, reuss, hashin_shtrikman {bulk_lower, bulk_upper,
// shear_lower, shear_upper}, bounds_tolerance, inside_bounds {voigt_reuss,
// hashin_shtrikman}; a broken bound a warning ending in `see` (Voigt and Reuss) or `why`
// (Hashin-Shtrikman).
template <std::size_t N>
void add_stiffness(const StiffnessVerdict<N>& v, const TensorBounds<N>& b, const std::vector<double>& fractions,
                   Json& effective, std::vector<std::string>& warnings, const std::string& see, const std::string& why);

// The engineering constants into `effective`: engineering {E_x, ..., G_.., nu_..} and
// anisotropy {universal (, normal, shear in 2D)}.
void add_engineering(const EngineeringConstants& k, Json& effective);

// A judged modulus of the mixed load into `effective`: inside_bounds {voigt_reuss,
// hashin_shtrikman}; a broken bound a warning ending in (`why`).
void add_modulus_verdict(const ModulusVerdict& v, Json& effective, std::vector<std::string>& warnings,
                         const std::string& why);

// Levin's relation beside a thermal expansion in `thermal` (levin, levin_difference); more
// than kLevinTolerance off a warning ending in `advice`.
template <std::size_t N>
void add_levin(const std::array<double, N>& expansion, const std::array<double, N>& levin, Json& thermal,
               std::vector<std::string>& warnings, const std::string& advice);

}  // namespace grainmesh
