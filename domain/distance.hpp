// Signed distance functions d(p) that describe a domain: d < 0 inside, d = 0 on the
// boundary, d > 0 outside (thesis eq. 2.1). Primitives are exact Euclidean distances;
// the Boolean compositions (thesis eq. 3.3, 3.5, 3.8) are the usual min/max bounds, whose
// zero level set is exactly the composed boundary.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

class DistanceFunction {
 public:
  // One node of a distance expression. Nodes are immutable and may be shared, so a
  // DistanceFunction is cheap to copy and safe to evaluate from several threads.
  struct Node {
    virtual ~Node() = default;
    virtual double eval(Vec2 p) const = 0;
    // A box containing every point with d <= 0.
    virtual Box bounds() const = 0;
    // Vertices of polygon-like primitives: candidate fixed points for the mesher.
    virtual void vertices(std::vector<Vec2>& out) const { (void)out; }
    // Lowers h to the size that curved primitives ask for at p: angle R + gradient |d|,
    // where R is the radius of curvature of the primitive's boundary at its point nearest
    // to p and d the primitive's own distance. Straight primitives leave h alone.
    virtual void limit_by_curvature(Vec2 p, double angle, double gradient, double& h) const {
      (void)p, (void)angle, (void)gradient, (void)h;
    }
  };

  explicit DistanceFunction(std::shared_ptr<const Node> node);

  double operator()(Vec2 p) const { return node_->eval(p); }
  Box bounds() const { return node_->bounds(); }
  std::vector<Vec2> vertices() const;
  // min over curved primitives of (angle R + gradient |d|); +infinity without any.
  double curvature_size(Vec2 p, double angle, double gradient) const;
  const std::shared_ptr<const Node>& node() const { return node_; }

 private:
  std::shared_ptr<const Node> node_;
};

// Disk of the given radius (> 0).
DistanceFunction circle(Vec2 centre, double radius);
// Ellipse with semi-axes a along x and b along y (> 0): the zero level set of thesis
// eq. 3.2, ((x-cx)/a)^2 + ((y-cy)/b)^2 = 1, but with the exact Euclidean distance.
DistanceFunction ellipse(Vec2 centre, double a, double b);
// Axis-aligned rectangle [lo.x, hi.x] x [lo.y, hi.y], lo < hi.
DistanceFunction rectangle(Vec2 lo, Vec2 hi);
// Simple polygon: rings[0] is the outer boundary, further rings are holes; any
// orientation, convex or not. Throws GeometryError when the rings are not a valid
// simple polygon with holes (see polygon.hpp).
DistanceFunction polygon(std::vector<std::vector<Vec2>> rings);

// min(d_1, ..., d_n), n >= 1 (eq. 3.3).
DistanceFunction unite(std::vector<DistanceFunction> parts);
// max(d_a, -d_b): a with b removed (eq. 3.5).
DistanceFunction subtract(DistanceFunction a, DistanceFunction b);
// max(d_1, ..., d_n), n >= 1 (eq. 3.8).
DistanceFunction intersect(std::vector<DistanceFunction> parts);
// The domain moved by offset: d(p - offset).
DistanceFunction translate(DistanceFunction d, Vec2 offset);

// Gradient of d at p by forward differences with step `step` (thesis eq. 2.13 uses
// this to project points onto the zero level set).
Vec2 numerical_gradient(const DistanceFunction& d, Vec2 p, double dp, double step);

// Moves p onto the zero level set of d by repeated first-order projection
// p <- p - d grad d / |grad d|^2, at most max_steps times or until |d| <= tolerance.
// Returns the projected point; `step` is the finite-difference step.
Vec2 project_to_zero(const DistanceFunction& d, Vec2 p, double step, double tolerance,
                     int max_steps = 8);

}  // namespace grainmesh
