// tessellation.json: the tessellation stage's output and the mesh stage's input.
// Schema (version 1), lengths in the config's unit:
//   format      "grainmesh-tessellation"; version 1
//   domain      {width, height, periodic}
//   phases      [{name, target_fraction, rest, E, nu}]
//   grains      [{id, phase, seed: [x, y], area, neighbours: [grain ids], matrix}]
//   vertices    [[x, y]]                       #V positions
//   edges       [[v0, v1, left, right]]        regions left/right of v0 -> v1, -1 outside
//   regions     [{grain, phase, rings: [[vertex ids]]}]  rings[0] outer, others holes;
//               every ring counter-clockwise
//   partners    {x: [[left, right]], y: [[bottom, top]]}  periodic vertex pairs
//   statistics  the TessellationStats fields, and the descriptors (descriptors_json)
// Version 2 (3D), the same keys where they mean the same, and:
//   domain      {width, height, depth, periodic}
//   grains      [{id, phase, seed: [x, y, z], volume, faces, neighbours, matrix (binder
//               mode's matrix grain only: true)}]
//   vertices    [[x, y, z]]
//   faces       [{back, front, ring: [vertex ids]}]  ring's right-hand normal from back
//               into front; front -1 on the box
//   regions     [{grain, phase, faces: [face ids]}]
//   partners    {x, y, z: [[low, high]]}
//   statistics  the Tessellation3Stats fields (binder_* in binder mode only), contiguity {PHASE: value}
// Doubles are written in shortest round-trip form, so reading gives the same bits.
#pragma once

#include <string>
#include <type_traits>

#include <nlohmann/json_fwd.hpp>

#include "tessellate/tessellation.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

std::string tessellation_to_json(const Tessellation& t);

// Its statistics, as tessellation.json and the reports carry them: the TessellationStats
// fields, phases [{name, target_fraction, achieved_fraction, grains}] and the descriptors.
nlohmann::ordered_json statistics_json(const Tessellation& t);

// The WC-Co descriptors of a 2D or 3D tessellation's phases (PhaseStats), as
// tessellation.json's statistics and the reports carry them: {contiguity,
// intercept_length, mean_free_path}, each {PHASE: value}, null where undefined (no
// boundary; no other phase touching).
nlohmann::ordered_json descriptors_json(const std::vector<Phase>& phases, const std::vector<PhaseStats>& stats);

// The phases as the reports give them: [{name, target_fraction, achieved_fraction, grains}].
nlohmann::ordered_json phases_json(const Tessellation& t);
// The same from the phases and their statistics (of a 2D or a 3D tessellation).
nlohmann::ordered_json phases_json(const std::vector<Phase>& phases, const std::vector<PhaseStats>& stats);

// The tessellation of a plane (D = 2) or solid (D = 3) cell.
template <int D>
using CellTessellation = std::conditional_t<D == 2, Tessellation, Tessellation3>;

// Parses and validates a tessellation.json of D dimensions (version 1 in 2D, 2 in 3D,
// read back bit for bit); errors (GeometryError) start with `source`, and one of the other
// dimension is refused by its version.
template <int D>
CellTessellation<D> tessellation_from_json(const std::string& text, const std::string& source);
template <>
Tessellation tessellation_from_json<2>(const std::string& text, const std::string& source);
template <>
Tessellation3 tessellation_from_json<3>(const std::string& text, const std::string& source);

// The version a tessellation.json says it is (1: 2D, 2: 3D), 0 when it says none.
int tessellation_version(const std::string& text);

// Version 2: a 3D tessellation, written and read back bit for bit.
std::string tessellation_to_json(const Tessellation3& t);
// Its statistics, as tessellation.json and the reports carry them (phases as in 2D, and
// contiguity {PHASE: value}).
nlohmann::ordered_json statistics_json(const Tessellation3Stats& s, const std::vector<Phase>& phases);
nlohmann::ordered_json statistics_json(const Tessellation3& t);

}  // namespace grainmesh
