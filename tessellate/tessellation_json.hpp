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
// Doubles are written in shortest round-trip form, so reading gives the same bits.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "tessellate/tessellation.hpp"

namespace grainmesh {

std::string tessellation_to_json(const Tessellation& t);

// The WC-Co descriptors of `t` (TessellationStats), as tessellation.json's statistics and
// the reports carry them: {contiguity, intercept_length, mean_free_path}, each
// {PHASE: value}, null where undefined (no boundary; no other phase touching).
nlohmann::ordered_json descriptors_json(const Tessellation& t);

// The phases as the reports give them: [{name, target_fraction, achieved_fraction, grains}].
nlohmann::ordered_json phases_json(const Tessellation& t);

// Parses and validates; errors (GeometryError) start with `source`.
Tessellation tessellation_from_json(const std::string& text, const std::string& source);

}  // namespace grainmesh
