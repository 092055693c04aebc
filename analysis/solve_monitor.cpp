#include "analysis/solve_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "common/format.hpp"

namespace grainmesh {

namespace {

constexpr std::array<const char*, 3> kComponent{"x", "y", "z"};

// The number after `key` in `l`, or NaN when `key` is not there.
double number_after(std::string_view l, std::string_view key) {
  const auto at = l.find(key);
  if (at == std::string_view::npos) return NAN;
  const std::string rest(l.substr(at + key.size()));
  return std::strtod(rest.c_str(), nullptr);  // also reads "nan" and "inf"
}

// "(a b c)" after `key`: its three numbers.
bool vector_after(std::string_view l, std::string_view key, std::array<double, 3>& v) {
  const auto at = l.find(key);
  if (at == std::string_view::npos) return false;
  const std::string rest(l.substr(at + key.size()));
  const char* p = rest.c_str();
  while (*p == ' ' || *p == '(') ++p;
  char* end = nullptr;
  for (double& x : v) {
    x = std::strtod(p, &end);
    p = end;
  }
  return true;
}

}  // namespace

SolveMonitor::State SolveMonitor::feed(std::string_view text) {
  while (!text.empty()) {
    const auto nl = text.find('\n');
    if (nl == std::string_view::npos) {
      partial_.append(text);
      break;
    }
    partial_.append(text.substr(0, nl));
    text.remove_prefix(nl + 1);
    line(partial_);
    partial_.clear();
  }
  return state_;
}

void SolveMonitor::line(std::string_view l) {
  if (l.find("Solving for D") != std::string_view::npos) {
    const auto at = l.find("Solving for D") + 13;
    const int c = at < l.size() && l[at] >= 'x' && l[at] <= 'z' ? l[at] - 'x' : -1;
    if (c < 0) return;
    if (c == 2) components_ = 3;  // Dz is solved in 3D only
    residual_[c] = number_after(l, "Initial residual = ");
    if (c == 0) ++corrections_;
    if (!std::isfinite(residual_[c]) && (state_ == State::running || state_ == State::converged)) {
      state_ = State::diverging;
      measure_ = residual_[c];
      worst_component_ = c;
    }
  } else if (l.find("areaIntegrate(") != std::string_view::npos && l.find(") of sigmaD = (") != std::string_view::npos) {
    // A symmTensor (xx xy xz yy yz zz) integrated over a side: the traction's components,
    // xx xy xz on left and right, xy yy yz on bottom and top, xz yz zz on back and front.
    const auto open = l.find("areaIntegrate(") + 14;
    const std::string_view side = l.substr(open, l.find(')', open) - open);
    const int normal = side == "left" || side == "right" ? 0 : side == "bottom" || side == "top" ? 1 : 2;
    static constexpr std::array<std::array<int, 3>, 3> kRow{{{0, 1, 2}, {1, 3, 4}, {2, 4, 5}}};
    const std::string rest(l.substr(l.find(") of sigmaD = (") + 15));
    const char* p = rest.c_str();
    for (int k = 0; k < 6; ++k) {
      char* end = nullptr;
      const double v = std::strtod(p, &end);
      if (end == p) break;
      if (std::find(kRow[normal].begin(), kRow[normal].end(), k) != kRow[normal].end()) forces_.push_back(v);
      p = end;
    }
  } else if (vector_after(l, "min(region0) of D =", low_)) {
  } else if (vector_after(l, "max(region0) of D =", high_)) {
    judge();  // the last of a correction's lines that the measure needs
  }
}

double SolveMonitor::stress_change() const {
  if (static_cast<int>(changes_.size()) < o_.stress_window) return INFINITY;
  return *std::max_element(changes_.begin(), changes_.end());
}

void SolveMonitor::judge() {
  if (!forces_.empty()) {
    double scale = 0.0, change = 0.0;
    for (double f : forces_) scale = std::max(scale, std::abs(f));
    if (previous_forces_.size() == forces_.size()) {
      for (std::size_t k = 0; k < forces_.size(); ++k) change = std::max(change, std::abs(forces_[k] - previous_forces_[k]));
      changes_.push_back(scale > 0.0 ? change / scale : (change > 0.0 ? INFINITY : 0.0));
      if (static_cast<int>(changes_.size()) > o_.stress_window) changes_.pop_front();
    }
    previous_forces_ = std::move(forces_);
    forces_.clear();
  }
  if (state_ != State::running && state_ != State::converged) return;  // stopped: kept as it was
  std::array<double, 3> range{};
  double scale = 0.0;
  for (int c = 0; c < components_; ++c) {
    range[c] = high_[c] - low_[c];
    if (!(range[c] <= scale)) scale = range[c];  // NaN wins
  }
  measure_ = 0.0;
  for (int c = 0; c < components_; ++c) {
    const double w = scale > 0.0 ? residual_[c] * range[c] / scale : residual_[c];
    if (!(w <= measure_)) {  // NaN wins
      measure_ = w;
      worst_component_ = c;
    }
  }
  if (!std::isfinite(measure_) || !std::isfinite(scale) || (o_.diverged_range > 0.0 && scale > o_.diverged_range)) {
    state_ = State::diverging;
    return;
  }
  if (state_ == State::converged) {
    // Will the case's own stop come? Its residual must keep halving until below its tolerance.
    double own = 0.0;
    for (int c = 0; c < components_; ++c)
      if (o_.case_watches[c]) own = std::max(own, residual_[c]);
    if (own < o_.case_tolerance) return;
    if (own < 0.5 * best_) {
      best_ = own;
      best_at_ = corrections_;
    } else if (corrections_ - best_at_ >= o_.case_patience) {
      state_ = State::case_stuck;
    }
    return;
  }
  const bool settled = o_.stress_tolerance <= 0.0 || stress_change() <= o_.stress_tolerance;
  if (measure_ < o_.tolerance && settled) {
    state_ = State::converged;
    converged_at_ = corrections_;
    best_ = 1e300;
    best_at_ = corrections_;
    judge();  // the case's residual at this correction
  } else if (measure_ < 0.5 * best_) {
    best_ = measure_;
    best_at_ = corrections_;
  } else if (corrections_ - best_at_ >= o_.stall_corrections) {
    state_ = State::stalled;
  }
}

std::string SolveMonitor::diagnosis() const {
  const std::string after = " after " + std::to_string(corrections_) + " corrections";
  if (state_ == State::diverging) {
    if (!std::isfinite(measure_)) return "the displacement's residual became " + to_text(measure_) + after;
    double range = 0.0;
    for (int c = 0; c < components_; ++c) range = std::max(range, high_[c] - low_[c]);
    return "the displacement grew to a range of " + to_text(range) +
           " m, a thousand times what the load can give," + after;
  }
  if (state_ == State::stalled)
    return std::string("the ") + kComponent[worst_component_] + " displacement's residual has not fallen for " +
           std::to_string(o_.stall_corrections) + " corrections (OpenFOAM's " + to_text(residual_[worst_component_], 3) +
           ", against the whole field " + to_text(measure_, 3) + ", above " + to_text(o_.tolerance, 3) + ")";
  return {};
}

}  // namespace grainmesh
