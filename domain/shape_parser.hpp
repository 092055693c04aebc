// Text form of distance functions, as written in configuration files:
//
//   circle(cx, cy, r)            ellipse(cx, cy, a, b)       rectangle(x1, y1, x2, y2)
//   polygon(x y, x y, x y, ...; x y, x y, x y, ...)     outer ring; each ';' starts a hole
//   union(S, S, ...)   difference(S, S)   intersection(S, S, ...)   translate(dx, dy, S)
//
// Numbers are decimal literals (1, -0.5, 2.5e-3). Whitespace is free.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/geometry.hpp"
#include "domain/distance.hpp"

namespace grainmesh {

// Parses a shape. `what` names the source (a config key) in error messages; syntax errors
// throw ConfigError, invalid geometry (a self-intersecting polygon) GeometryError, both
// starting with `what`.
DistanceFunction parse_shape(std::string_view text, const std::string& what);

// Parses "x y, x y, ..." (an empty text gives no points). Throws ConfigError.
std::vector<Vec2> parse_point_list(std::string_view text, const std::string& what);

// Parses whitespace-separated numbers, exactly `count` of them. Throws ConfigError.
std::vector<double> parse_numbers(std::string_view text, std::size_t count, const std::string& what);

}  // namespace grainmesh
