// A convergence study's limits judged against the bounds of its cell (grainmesh converge).
// The bounds hold for the exact answer, so a limit outside them says that the levels are
// not yet in the asymptotic range, whatever the extrapolation's order looks like. The same
// verdicts as an answer's (verdicts.hpp), named as the limits of its quantities.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "analysis/answer.hpp"

namespace grainmesh {

// Each quantity's limit, by the name it has in the study (stiffness_name: "C11", ...; or
// "modulus").
using StudyLimits = std::vector<std::pair<std::string, double>>;

// The sentences of the bounds `finest` (the finest level's answer) was judged by that the
// limits break: a periodic answer's stiffness with each studied entry set to its limit (the
// others the finest level's), Voigt and Reuss in the positive semi-definite order, then
// Hashin-Shtrikman on its bulk and shear moduli; or the mixed modulus's limit against its
// bounds. Quantities the answer does not bound (the volume-average modulus) are not judged.
template <std::size_t N>
std::vector<std::string> limits_outside_bounds(const Answer<N>& finest, const StudyLimits& limits);

}  // namespace grainmesh
