// The contiguity of a phase (the share of its boundary with itself) and trading grains'
// labels to move it toward a target.
#pragma once

#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "common/random.hpp"

namespace grainmesh {

// Each grain's neighbours and the length of boundary it shares with each (summed over
// their edges; a grain's boundary with itself left out).
using SharedBoundaries = std::vector<std::vector<std::pair<int, double>>>;

// The contiguity 2 L_aa / (2 L_aa + L_ab) of `phase` under `label` (0 without boundary).
double labelled_contiguity(const std::vector<int>& label, const SharedBoundaries& shared, int phase);

// Moves the contiguity of `phase` toward `target` by trading labels: a grain of the phase
// and a like-sized grain of another phase swap theirs, the phase's summed area staying
// within `slack` of `target_area` (or within where it started, when further). Greedy:
// each of the phase's grains in an order drawn from `rng` takes the trade that brings the
// contiguity nearest the target, sweep after sweep until within 0.002 or no trade helps.
// Returns the contiguity reached.
double arrange_contiguity(std::vector<int>& label, const std::vector<double>& areas, const SharedBoundaries& shared,
                          int phase, double target, double target_area, double slack, Rng& rng);

// arrange_contiguity toward `target`; when it ends farther than `tolerance` from it, the
// lowest and highest contiguity the trades reach from the same start (trades toward 0 and
// toward 1), else none.
std::optional<std::pair<double, double>> reach_contiguity(std::vector<int>& label, const std::vector<double>& areas,
                                                          const SharedBoundaries& shared, int phase, double target,
                                                          double target_area, double slack, double tolerance, Rng& rng);

// Binder mode's contacts: the count n in [0, most] whose contiguity(n) (not falling as n
// grows) is nearest `target`, the fewest that reach it or one fewer when that is nearer,
// found by bisection on n.
int contacts_nearest(int most, double target, const std::function<double(int)>& contiguity);

}  // namespace grainmesh
