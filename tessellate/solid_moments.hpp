// A closed polyhedron's volume and centroid from its boundary's triangles (each face
// fanned from one of its points, turned outward): the sum of the signed tetrahedra they
// make with a fixed origin.
#pragma once

#include "common/vec3.hpp"

namespace grainmesh {

class SolidMoments {
 public:
  // Near the polyhedron, for rounding: a point of it, or its seed.
  explicit SolidMoments(Vec3 origin) : origin_(origin) {}

  void add_triangle(Vec3 a, Vec3 b, Vec3 c) {
    a = a - origin_;
    b = b - origin_;
    c = c - origin_;
    const double v = dot(a, cross(b, c)) / 6.0;
    volume_ += v;
    moment_ += (v / 4.0) * (a + b + c);
  }
  double volume() const { return volume_; }
  // The origin while the volume is not positive.
  Vec3 centroid() const { return volume_ > 0.0 ? origin_ + moment_ / volume_ : origin_; }

 private:
  Vec3 origin_;
  double volume_ = 0.0;
  Vec3 moment_{};
};

}  // namespace grainmesh
