// Judging a running solidDisplacementFoam from its log: converged, stalled or diverging.
//
// OpenFOAM normalises each component's residual by that component's own magnitude, so a
// component whose exact solution is zero (y under the default load on one material) has
// a residual of rounding noise that never falls: the solve would wait for ever. The
// measure here weighs each component's residual by its share of the displacement: the
// residual of component c times range(D_c) / max over c' of range(D_c'), range being the
// largest minus the smallest cell value. That is the residual against the scale of the
// whole displacement field; for the component that carries the load it is OpenFOAM's own.
#pragma once

#include <array>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

namespace grainmesh {

class SolveMonitor {
 public:
  struct Options {
    double tolerance = 1e-8;  // converged once the measure falls below it
    // Stalled: the measure has not halved for this many corrections. A converging solve
    // halves it every few (the default cell: 50 corrections from 1 to 1e-8).
    int stall_corrections = 500;
    // Diverging: a displacement range above this (metres), a thousand times what the load
    // can produce; 0 = not checked.
    double diverged_range = 0.0;
    // The case's own stop (export/foam_solver.hpp, CaseStop): OpenFOAM's residual of the watched
    // components below case_tolerance. After the measure converged, the case gets
    // case_patience corrections to halve its own; else it is stuck (a component near zero).
    std::array<bool, 3> case_watches{true, true, true};
    double case_tolerance = 1e-8;
    int case_patience = 50;
    // The effective stress has settled when no correction of the last stress_window changed
    // the logged forces (surfaceFieldValue areaIntegrate of sigma on the loaded sides) by
    // more than stress_change() measures against.
    int stress_window = 5;
    double stress_tolerance = 0.0;  // > 0: converged only once stress_change() is below it too
  };
  enum class State {
    running,     // not yet converged
    converged,   // the measure is below the tolerance (and the stress has settled); the case will stop on its own
    case_stuck,  // converged, but the case's own stop will not come: stop it at converged_at()
    stalled,
    diverging,
  };

  explicit SolveMonitor(Options options) : o_(options) {}

  // Reads the next piece of the log (any split: partial lines wait for their end).
  State feed(std::string_view text);
  State state() const { return state_; }

  // Corrections so far; the one at which the measure first fell below the tolerance (0
  // before); the measure at the last, and OpenFOAM's residuals of the components solved
  // there (x and y; z too in 3D).
  int corrections() const { return corrections_; }
  int converged_at() const { return converged_at_; }
  double measure() const { return measure_; }
  std::vector<double> residuals() const { return {residual_.begin(), residual_.begin() + components_}; }
  // How much the logged forces changed at most over the last stress_window corrections,
  // relative to the largest of their components (infinite before that many corrections,
  // or when the case logs none).
  double stress_change() const;
  // What went wrong, for a stalled or diverging solve: "the y displacement's residual ..."
  std::string diagnosis() const;

 private:
  void line(std::string_view l);
  void judge();

  Options o_;
  State state_ = State::running;
  std::string partial_;
  int corrections_ = 0, converged_at_ = 0;
  int components_ = 2;  // 3 once Dz is solved (a 3D case)
  std::array<double, 3> residual_{1.0, 1.0, 1.0}, low_{}, high_{};
  double measure_ = 1.0;
  double best_ = 1e300;  // the measure (after convergence: the case's) when it last halved, and the correction it did
  int best_at_ = 0;
  int worst_component_ = 0;
  std::vector<double> forces_, previous_forces_;  // this correction's logged force components, and the last's
  std::deque<double> changes_;                    // their relative change at each of the last corrections
};

}  // namespace grainmesh
