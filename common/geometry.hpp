// Plain 2D geometry shared by every stage: points, vectors and axis-aligned boxes.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainmesh {

// A point or vector in the plane, in the caller's length unit.
struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  friend bool operator==(const Vec2&, const Vec2&) = default;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
inline Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
inline Vec2& operator+=(Vec2& a, Vec2 b) { a.x += b.x; a.y += b.y; return a; }
inline Vec2& operator-=(Vec2& a, Vec2 b) { a.x -= b.x; a.y -= b.y; return a; }

inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
// z-component of the 3D cross product: > 0 when b turns left from a.
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm2(Vec2 a) { return dot(a, a); }
// Plain sqrt: mesh coordinates never come near overflow, and std::hypot's care costs 5x.
inline double norm(Vec2 a) { return std::sqrt(dot(a, a)); }
// a rotated by +90 degrees.
inline Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
inline bool is_finite(Vec2 a) { return std::isfinite(a.x) && std::isfinite(a.y); }

// Where along the segment ab its point nearest p lies: a + t (b - a), t in [0, 1]; exactly
// 0 or 1 when that point is an end (0 when a == b).
inline double segment_parameter(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double l2 = norm2(ab);
  return l2 > 0.0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
}
// Squared distance from p to the segment ab at its parameter t (segment_parameter).
inline double segment_distance2(Vec2 p, Vec2 a, Vec2 b, double t) { return norm2((p - a) - t * (b - a)); }
// Squared distance from p to the segment ab (a point when a == b).
inline double segment_distance2(Vec2 p, Vec2 a, Vec2 b) { return segment_distance2(p, a, b, segment_parameter(p, a, b)); }

// Twice the signed area of triangle abc: > 0 when a, b, c turn counter-clockwise.
// Floating point; use orient2d() where the sign must be right.
inline double signed_area2(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }

// Closed axis-aligned box [lo.x, hi.x] x [lo.y, hi.y]; empty when lo > hi.
struct Box {
  Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  bool empty() const { return !(lo.x <= hi.x && lo.y <= hi.y); }
  double width() const { return hi.x - lo.x; }
  double height() const { return hi.y - lo.y; }
  Vec2 centre() const { return 0.5 * (lo + hi); }

  void extend(Vec2 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  void extend(const Box& b) {
    if (b.empty()) return;
    extend(b.lo);
    extend(b.hi);
  }
  bool contains(Vec2 p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
};

inline Box intersection(const Box& a, const Box& b) {
  return {{std::max(a.lo.x, b.lo.x), std::max(a.lo.y, b.lo.y)},
          {std::min(a.hi.x, b.hi.x), std::min(a.hi.y, b.hi.y)}};
}

}  // namespace grainmesh
