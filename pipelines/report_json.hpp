// How an answer (analysis/answer.hpp) is written into report.json, one writer for 2D and
// 3D (Voigt size N = 3 or 6), so that both dimensions give the fields of
// docs/report.schema.json the same names and shapes: tensors by Voigt component ({xx, yy,
// ...}), stiffnesses by Cij (i <= j, by Voigt index: 1, 2, 6 in 2D; 1 to 6 in 3D), load
// cases as an array, each phase's stresses by its name.
#pragma once

#include <cstddef>
#include <filesystem>

#include "analysis/answer.hpp"
#include "pipelines/report.hpp"

namespace grainmesh {

// report.json's `effective` (docs/report.md): the mixed load's modulus, or the periodic
// load cases' stiffness, with the bounds, verdicts, engineering constants, thermal
// expansion and each solve (its result directory relative to `dir`).
template <std::size_t N>
Json effective_json(const Answer<N>& a, const std::filesystem::path& dir);

// report.json's `stresses`: {STATE: {PHASE: {volume_fraction, mean {xx, yy, zz, yz, xz,
// xy}, von_mises, max_principal, hydrostatic (each a distribution: mean, std, p50, p90,
// p99, max), partition (when loaded)}}}.
template <std::size_t N>
Json stresses_json(const Answer<N>& a);

}  // namespace grainmesh
