// The wall-clock guard of a run: every long loop asks it whether time is up, so no input
// can keep an unattended run busy for ever. A default Deadline never passes.
#pragma once

#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "common/errors.hpp"

namespace grainmesh {

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;

  Deadline() = default;
  // `seconds` from now; infinity (or anything not finite and positive) for none. `name`
  // is what the user sets it by (a config key), for the message.
  static Deadline after(double seconds, std::string name = "the time limit") {
    Deadline d;
    d.name_ = std::move(name);
    if (std::isfinite(seconds) && seconds > 0) {
      d.limit_ = seconds;
      d.end_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    }
    return d;
  }

  bool passed() const { return end_ != Clock::time_point::max() && Clock::now() >= end_; }
  // Once the deadline has passed, throws TimeLimitError "NAME = S s reached WHEN: raise
  // it if the run should take longer".
  void check(const std::string& when) const {
    if (!passed()) return;
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", limit_);
    throw TimeLimitError(name_ + " = " + limit + " s reached " + when + ": raise it if the run should take longer");
  }
  // The limit it was made with, in seconds; infinity for none.
  double limit_seconds() const { return limit_; }
  // Seconds left (>= 0); infinity for none.
  double remaining_seconds() const {
    if (end_ == Clock::time_point::max()) return limit_;
    return std::max(0.0, std::chrono::duration<double>(end_ - Clock::now()).count());
  }

 private:
  Clock::time_point end_ = Clock::time_point::max();
  double limit_ = std::numeric_limits<double>::infinity();
  std::string name_ = "the time limit";
};

}  // namespace grainmesh
