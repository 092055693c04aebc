// The four sides of a rectangular cell, one numbering for every stage: left (x = lo.x),
// right (x = hi.x), bottom (y = lo.y), top (y = hi.y); kNoSide for anything else. A side
// and its periodic partner differ in the lowest bit (left ^ 1 = right, bottom ^ 1 = top).
#pragma once

#include <array>
#include <cmath>

#include "common/geometry.hpp"

namespace grainmesh {

enum CellSide : int { kLeft = 0, kRight = 1, kBottom = 2, kTop = 3, kNoSide = 4 };

// The sides in the order a counter-clockwise walk round the cell meets them.
inline constexpr std::array<CellSide, 4> kSidesCounterClockwise{kBottom, kRight, kTop, kLeft};

inline const char* side_name(CellSide s) {
  constexpr std::array<const char*, 5> names{"left", "right", "bottom", "top", "boundary"};
  return names[s];
}

// True for left and right, whose points share x.
inline bool is_vertical(CellSide s) { return s == kLeft || s == kRight; }
// The coordinate a side fixes: x for left and right, y for bottom and top.
inline double side_coordinate(const Box& cell, CellSide s) {
  return s == kLeft ? cell.lo.x : s == kRight ? cell.hi.x : s == kBottom ? cell.lo.y : cell.hi.y;
}

// Whether p lies on side s, within `tol` (0: exactly; points on a side carry its coordinate).
inline bool on_side(const Box& cell, Vec2 p, CellSide s, double tol = 0.0) {
  return std::abs((is_vertical(s) ? p.x : p.y) - side_coordinate(cell, s)) <= tol;
}

// The side the segment ab runs along (both ends on it, within `tol`), else kNoSide.
inline CellSide side_along(const Box& cell, Vec2 a, Vec2 b, double tol = 0.0) {
  for (CellSide s : {kLeft, kRight, kBottom, kTop})
    if (on_side(cell, a, s, tol) && on_side(cell, b, s, tol)) return s;
  return kNoSide;
}

}  // namespace grainmesh
