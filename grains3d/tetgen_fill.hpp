// Filling one closed surface with tetrahedra by TetGen, run as a program (Debian ships it
// without a library): the surface written as a .smesh, TetGen told to keep its triangles
// (-Y), its output read back. TetGen 1.5 trips an assertion on a few inputs and never
// finishes on a few others (in point location, whatever the quality switches); another
// point insertion order (its -b switch) gets past both. So every try runs under a time
// budget scaled to the tetrahedra it should make, and a try that fails or overruns is
// followed by the next order; the first that works is used, so the result is
// deterministic.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "common/deadline.hpp"
#include "common/interrupt.hpp"
#include "common/vec3.hpp"

namespace grainmesh {

// A scratch directory for TetGen's files (under the system's temporary directory), removed
// with it, and on an interrupt (interrupt.hpp).
class ScratchDirectory {
 public:
  ScratchDirectory();
  ~ScratchDirectory();
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  TemporaryPath registered_;
};

struct TetgenOptions {
  double radius_edge = 1.3;        // -q: radius-edge ratio bound
  double min_dihedral_deg = 15.0;  // -q: smallest dihedral angle bound
  double max_volume = 0.0;         // -a: volume bound (the surface's units cubed); > 0
  Deadline deadline{};             // the run's: passing it throws TimeLimitError
  // Each try's budget: this much, plus this much per tetrahedron the volume bound asks for
  // (TetGen makes tens of thousands a second; a hung try makes none).
  double budget_seconds = 2.0;
  double budget_seconds_per_tet = 2e-4;
};

// The point insertion orders tried, in order (TetGen's -b suffixes; "" its default).
inline constexpr const char* kTetgenOrders[] = {"", "b/1", "b/0.5"};

struct TetgenFill {
  std::vector<Vec3> points;               // the surface's points first, in their order, then TetGen's
  std::vector<std::array<int, 4>> tets;   // positive
  std::string switches;                   // the try that worked
  int tries = 0;
};

// Fills the closed surface (`points`, `triangles` turning outward, point ids) in `dir`,
// its files named NAME.*; `what` names it in messages ("region 123 (grain 45)").
// Throws GeometryError when TetGen is not installed, and when every order fails or
// overruns: naming `what`, what each try did, and the .smesh, kept in the system's
// temporary directory to be looked at or reported; TimeLimitError when the deadline passes.
TetgenFill tetgen_fill(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                       const TetgenOptions& options, const std::filesystem::path& dir, const std::string& name,
                       const std::string& what);

// The budget of one try on a region of `volume` at `options.max_volume` per tetrahedron.
double tetgen_budget(const TetgenOptions& options, double volume);

}  // namespace grainmesh
