// The answer's lines in a run's summary on stdout, from the typed answer, one contract for
// 2D and 3D (N the Voigt size): the mixed load's modulus with its bounds, or the periodic
// stiffness's leading entries with K, G and its symmetry error, and the free thermal
// expansion under a temperature change.
#pragma once

#include <cstddef>

#include "analysis/answer.hpp"

namespace grainmesh {

template <std::size_t N>
void print_answer(const Answer<N>& a);

}  // namespace grainmesh
