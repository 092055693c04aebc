// Filling one closed surface with tetrahedra by TetGen's library (Debian's libtet), run in
// worker processes of ours: the surface is sent to a worker, TetGen told to keep its
// triangles (-Y), the tetrahedra sent back. TetGen 1.5 trips an assertion on a few inputs
// and never finishes on a few others (in point location, whatever the quality switches);
// another point insertion order (its -b switch) gets past both. So every try runs under a
// time budget scaled to the tetrahedra it should make; a worker that fails, dies or
// overruns is killed and replaced, and the next order tried; the first that works is
// used, so the result is deterministic. A worker is a process of its own because a hung
// TetGen call can only be stopped by ending its process; workers are forked once and
// serve many surfaces, so a cell of a thousand grains costs two forks, not thousands of
// programs started and files written and parsed.
#pragma once

#include <array>
#include <memory>
#include <mutex>
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

// TetGen's workers: started when first needed (at most as many as threads fill at once),
// killed with the object, and on an interrupt (interrupt.hpp: each is a registered child).
// fill() may be called from several threads at once.
class TetgenWorkers {
 public:
  TetgenWorkers();
  ~TetgenWorkers();
  TetgenWorkers(const TetgenWorkers&) = delete;
  TetgenWorkers& operator=(const TetgenWorkers&) = delete;

  // Fills the closed surface (`points`, `triangles` turning outward, point ids); `what`
  // names it in messages ("region 123 (grain 45)"). Throws GeometryError when every order
  // fails or overruns: naming `what`, what each try did, and the surface, kept as a .smesh
  // in the system's temporary directory to be looked at or reported; TimeLimitError when
  // the deadline passes; IoError when no worker can be started.
  TetgenFill fill(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                  const TetgenOptions& options, const std::string& what);

  struct Worker;

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<Worker>> idle_;
};

// The budget of one try on a region of `volume` at `options.max_volume` per tetrahedron.
double tetgen_budget(const TetgenOptions& options, double volume);

}  // namespace grainmesh
