// Filling one closed surface with tetrahedra by TetGen's library (Debian's libtet), run in
// a helper program of ours, grainmesh-tetgen, started fresh for each try: the surface is
// sent over a socket, TetGen told to keep its triangles (-Y), the tetrahedra sent back.
// TetGen 1.5 trips an assertion on a few inputs and never finishes on a few others (in
// point location, whatever the quality switches); another point insertion order (its -b
// switch) gets past both. So every try runs under a time budget scaled to the tetrahedra
// it should make; a try that fails, dies or overruns is stopped and the next order tried;
// the first that works is used. A process per try because a hung TetGen call can only be
// stopped by ending its process, and so that every fill starts from the same state: the
// mesh does not depend on which thread filled what before (long-lived workers forked from
// the run gave meshes differing with the thread count in the sanitizer build). No files:
// at 1,000 grains the fill went from 45 s (the tetgen program, its files and a polled wait)
// to 14 s.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "common/deadline.hpp"
#include "common/vec3.hpp"

namespace grainmesh {

// The point insertion orders tried, in order (TetGen's -b suffixes; "" its default).
inline const std::vector<std::string> kTetgenOrders{"", "b/1", "b/0.5"};

struct TetgenOptions {
  double radius_edge = 1.3;        // -q: radius-edge ratio bound
  double min_dihedral_deg = 15.0;  // -q: smallest dihedral angle bound
  double max_volume = 0.0;         // -a: volume bound (the surface's units cubed); > 0
  Deadline deadline{};             // the run's: passing it throws TimeLimitError
  // Each try's budget: this much, plus this much per tetrahedron the volume bound asks for
  // (TetGen makes tens of thousands a second; a hung try makes none).
  double budget_seconds = 2.0;
  double budget_seconds_per_tet = 2e-4;
  std::vector<std::string> orders = kTetgenOrders;  // the tries' -b suffixes, in order
};

struct TetgenFill {
  std::vector<Vec3> points;              // the surface's points first, in their order, then TetGen's
  std::vector<std::array<int, 4>> tets;  // positive
  std::string switches;                  // the try that worked
  int tries = 0;
};

// TetGen's helper: grainmesh-tetgen beside this program (found once). Each try's helper
// dies with the thread that spawned it (an interrupt ends the run, and so it). fill() may
// be called from several threads at once.
class TetgenRunner {
 public:
  // Throws GeometryError when the helper is not beside this program.
  TetgenRunner();

  // Fills the closed surface (`points`, `triangles` turning outward, point ids); `what`
  // names it in messages ("region 123 (grain 45)"). Throws GeometryError when every order
  // fails or overruns: naming `what`, what each try did, and the surface, kept as a .smesh
  // in the system's temporary directory to be looked at or reported; TimeLimitError when
  // the deadline passes; IoError when the helper cannot be started.
  TetgenFill fill(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                  const TetgenOptions& options, const std::string& what) const;

 private:
  std::string helper_;
};

// The budget of one try on a region of `volume` at `options.max_volume` per tetrahedron.
double tetgen_budget(const TetgenOptions& options, double volume);

}  // namespace grainmesh
