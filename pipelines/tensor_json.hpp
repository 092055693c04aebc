// How report.json names a tensor's components: a symmetric tensor by its Voigt components
// ({xx, yy, ...}), a stiffness by its entries Cij (i <= j, by Voigt index: 1, 2, 6 in 2D;
// 1 to 6 in 3D). One naming for every writer of report.json.
#pragma once

#include <array>
#include <cstddef>

#include "analysis/voigt.hpp"
#include "pipelines/report.hpp"

namespace grainmesh {

// {xx: .., yy: .., ...} of a tensor's Voigt components.
template <std::size_t N>
Json voigt_json(const std::array<double, N>& v) {
  Json out = Json::object();
  for (std::size_t k = 0; k < N; ++k) out[voigt_names<N>()[k]] = v[k];
  return out;
}

// {C11: .., C12: .., ...}: the entries i <= j of a symmetric stiffness, named by their Voigt
// indices (1, 2, 6 in 2D; 1 to 6 in 3D), row by row.
template <std::size_t N>
Json stiffness_json(const Stiffness<N>& c) {
  Json out = Json::object();
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i; j < N; ++j) out[stiffness_name<N>(i, j)] = c[i][j];
  return out;
}

}  // namespace grainmesh
