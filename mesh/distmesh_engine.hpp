// The DistMesh engine's insides, shared by its files (mesh/distmesh*.cpp) and by no one
// else: the engine class, its tuning constants and the helpers it is built on.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "common/spatial_grid.hpp"
#include "domain/size_grading.hpp"
#include "mesh/delaunay.hpp"
#include "mesh/distmesh_options.hpp"
#include "mesh/point_set.hpp"

namespace grainmesh::distmesh_detail {

// Above this many lattice points at the finest spacing, seeding starts from a quadtree.
inline constexpr double kMaxLatticePoints = 20000.0;
// Initial points keep this many sizes clear of a seeded boundary.
inline constexpr double kClear = 0.4;
// Optimisation keeps free points at least this x the local size inside a seeded boundary.
inline constexpr double kStarClearance = 0.05;
// The finish after the force iterations (fixed seeded boundary only): triangles below
// kMendBelow get Steiner points or lose crowding points; those still below kTryBelow get
// one trial point each. Each trial retriangulates the region, so they are bounded.
inline constexpr double kMendBelow = 0.7;
inline constexpr double kTryBelow = 0.6;
inline constexpr std::size_t kMaxTrials = 200;
// A Steiner point closer than this x the local size to the corners of its triangle only
// splits a sliver into slivers: none is added there.
inline constexpr double kSteinerClearance = 0.1;

// Points in a uniform hash grid, for "is there a point within r of p" with r up to the
// cell size. Linear in the number of points for evenly spread inputs.
class PointGrid {
 public:
  explicit PointGrid(double cell) : grid_(cell) {}
  void insert(Vec2 p) { grid_.add(grid_.cell_of(p.x), grid_.cell_of(p.y), p); }
  bool near(Vec2 p, double radius) const {
    const std::int64_t cx = grid_.cell_of(p.x), cy = grid_.cell_of(p.y);
    const std::int64_t reach = static_cast<std::int64_t>(std::ceil(radius / grid_.cell()));
    for (std::int64_t i = cx - reach; i <= cx + reach; ++i)
      for (std::int64_t j = cy - reach; j <= cy + reach; ++j)
        if (const std::vector<Vec2>* cell = grid_.at(i, j))
          for (const Vec2 q : *cell)
            if (norm2(q - p) < radius * radius) return true;
    return false;
  }

 private:
  HashGrid<Vec2> grid_;
};

// The size field the engine works with: absolute edge lengths. The user's relative size
// h is scaled so that its least value over the domain maps to h0 (the thesis' meaning
// of h0), graded where it grows faster than the problem allows, then limited by the
// curvature of curved boundaries.
struct AbsoluteSize final : SizeFunction::Node {
  explicit AbsoluteSize(SizeFunction r) : relative(std::move(r)) {}
  SizeFunction relative;
  double scale = 1.0;  // h0 / min h
  std::optional<SizeGrading> grading;
  std::vector<DistanceFunction> curved;
  double angle = 0.0, gradient = 0.0;

  void eval(std::span<const Vec2> p, std::span<double> out) const override {
    relative.eval(p, out);
    for (std::size_t i = 0; i < p.size(); ++i) {
      out[i] *= scale;
      if (grading) out[i] = grading->at(p[i], out[i]);
      for (const auto& c : curved) out[i] = std::min(out[i], c.curvature_size(p[i], angle, gradient));
    }
  }
  std::string describe() const override { return relative.describe(); }
};


// How the domain's boundary is made: `projected`, the thesis' way (points that leave the
// domain are projected back onto d = 0, boundary and interface points seeded and split
// as needed); `fixed`, the grains' way (the boundary is the given fixed points joined by
// the constraint segments, kept as they are; free points stay clear of it, and the
// finish adds and removes free points where triangles stay poor).
enum class BoundaryMode { projected, fixed };

// One run of Algorithm 1. Points 0 .. fixed-1 are the fixed points. Its steps are defined
// in distmesh_seeding.cpp (step 1), distmesh_forces.cpp (steps 2 to 5 and density
// control), distmesh_interface.cpp (Algorithm 3) and distmesh_finish.cpp (the finish).
class Engine {
 public:
  Engine(const DistMeshProblem& pb, const DistMeshOptions& opt)
      : pb_(pb),
        opt_(opt),
        h0_(pb.h0),
        geps_(opt.geps * pb.h0),
        deps_(std::sqrt(std::numeric_limits<double>::epsilon()) * pb.h0),
        proj_tol_(1e-10 * pb.h0),
        on_interface_tol_(1e-8 * pb.h0),
        mode_(pb.constraints.empty() ? BoundaryMode::projected : BoundaryMode::fixed) {}

  DistMeshResult run(Rng& rng);

 private:
  bool fixed_boundary() const { return mode_ == BoundaryMode::fixed; }
  std::vector<Vec2> lattice(double spacing) const;
  std::vector<Vec2> graded_points() const;
  void seed_points(Rng& rng);
  std::vector<Vec2> unique_fixed_points() const;
  double make_size_field(const std::vector<Vec2>& pts, const std::vector<double>& h);
  std::vector<double> checked_size(const std::vector<Vec2>& pts) const;
  int interface_mover(int a, int b, const std::vector<double>& di) const;
  void triangulate(bool from_scratch = false);
  void points_changed();
  void points_appended(std::size_t first, const std::vector<int>& near);
  void bar_forces();
  bool density_control();
  void move_points();
  void follow_interface();
  void project_boundary();
  double max_move_since_triangulation() const;
  std::size_t repair_interface();
  void optimize_stars(std::size_t first = 0);
  std::size_t insert_steiner_points();
  std::size_t remove_crowding_points();
  std::size_t try_steiner_points();
  std::pair<double, double> shortfall(double target) const;
  TriMesh compact() const;
  std::vector<int> interface_phase(const TriMesh& mesh) const;  // DistMeshResult::phase

  const DistMeshProblem& pb_;
  const DistMeshOptions& opt_;
  const double h0_, geps_, deps_, proj_tol_, on_interface_tol_;
  const BoundaryMode mode_;
  std::optional<SizeFunction> size_;  // absolute, set by seed_points

  PointSet p_;                               // #N positions, fixed first; interface flags
  std::vector<Vec2> pold_;                   // positions at the last triangulation
  std::vector<Vec2> before_;                 // positions at the start of the iteration
  Triangulation live_;                       // kept Delaunay by flips while points move
  bool live_valid_ = false;                  // false: the points changed, build anew
  std::vector<int> orphans_;                 // points in no triangle of live_
  std::vector<std::array<int, 3>> tris_;     // triangles with centroid inside
  std::vector<std::array<int, 2>> bars_;     // unique edges of tris_
  std::vector<char> on_boundary_;            // #N: on an edge of one triangle
  std::vector<char> bar_on_boundary_;        // #bars: an edge of one triangle
  std::vector<Vec2> force_, mid_;            // #N total force; #bars midpoints (at triangulation)
  std::vector<double> len_, d_, di_;         // #bars lengths; #N d, dI
  std::vector<double> bar_size_;             // #bars size field at the midpoints
  std::vector<double> point_size_;           // #N size at the points (absolute sizes only)
  std::vector<char> kept_;                   // #live triangles: inside the domain
  double sum_size2_ = 0.0;                   // sum of bar_size_ squared
  double len0_scale_ = 0.0;                  // wanted length / bar size, this iteration
  std::vector<double> dval_;                 // #N d at dpos_, the last exact evaluation
  std::vector<Vec2> dpos_;
  DistMeshStats stats_;
};


}  // namespace grainmesh::distmesh_detail
