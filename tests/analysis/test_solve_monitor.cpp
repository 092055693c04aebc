// The solve monitor on logs written as solidDisplacementFoam writes them: converged,
// converged with a component that is zero, stalled, diverging; read in any pieces.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "common/format.hpp"
#include "analysis/solve_monitor.hpp"

using namespace grainmesh;

namespace {

// One correction's lines: OpenFOAM's residuals of x and y, then the displacement's
// smallest and largest cell values (the case's volFieldValue function objects).
std::string correction(int n, double rx, double ry, double x_range, double y_range) {
  return "Iteration: " + std::to_string(n) + "\n\nGAMG:  Solving for Dx, Initial residual = " + to_text(rx, 12) +
         ", Final residual = 1e-3, No Iterations 2\nGAMG:  Solving for Dy, Initial residual = " + to_text(ry, 12) +
         ", Final residual = 1e-3, No Iterations 3\nExecutionTime = 0.1 s  ClockTime = 0 s\n\n"
         "volFieldValue displacement_min write:\n    min(region0) of D = (0 " + to_text(-0.5 * y_range, 12) +
         " 0)\n\nvolFieldValue displacement_max write:\n    max(region0) of D = (" + to_text(x_range, 12) + " " +
         to_text(0.5 * y_range, 12) + " 0)\n\n";
}

SolveMonitor::Options options() { return {.tolerance = 1e-8, .stall_corrections = 50, .diverged_range = 1e-6}; }

}  // namespace

TEST_CASE("the solve monitor: converged when every component's residual, weighed by its share, is small",
          "[solve]") {
  // Both components carry displacement: the measure is OpenFOAM's residual, y weighed by
  // its range against x's.
  std::string log;
  for (int n = 1; n <= 40; ++n) log += correction(n, std::pow(0.5, n), std::pow(0.5, n - 5), 1e-9, 1e-10);
  // In pieces of every size, even one byte at a time.
  for (const std::size_t piece : {std::size_t{1}, std::size_t{7}, std::size_t{4096}, log.size()}) {
    SolveMonitor m(options());
    for (std::size_t at = 0; at < log.size(); at += piece) m.feed(std::string_view(log).substr(at, piece));
    CHECK(m.state() == SolveMonitor::State::converged);
    CHECK(m.corrections() == 40);
  }
  SolveMonitor m(options());
  for (int n = 1; n <= 40; ++n) {
    const SolveMonitor::State s = m.feed(correction(n, std::pow(0.5, n), std::pow(0.5, n - 5), 1e-9, 1e-10));
    // y's residual is 32 times x's but y is a tenth of x: 2^-n * 3.2 < 1e-8 from n = 29.
    CHECK((s == SolveMonitor::State::converged) == (n >= 29));
  }
  CHECK(m.residuals()[1] == Approx(std::pow(0.5, 35)));
  CHECK(m.measure() < 1e-8);
}

TEST_CASE("the solve monitor: a component that is zero does not hold the solve up", "[solve]") {
  // One material under the default load: y is rounding noise whose own residual stays
  // near 0.2 for ever; its range falls with x's residual.
  auto noise = [](int n) {
    const double rx = std::pow(0.4, n);
    return correction(n, rx, 0.2, 1e-9, 10 * rx * 1e-9);
  };
  SolveMonitor m(options());
  int n = 0;
  while (m.state() == SolveMonitor::State::running && n < 60) m.feed(noise(++n));
  CHECK(m.state() == SolveMonitor::State::converged);
  CHECK(m.converged_at() == n);
  CHECK(n > 10);
  CHECK(n < 30);
  CHECK(m.residuals()[1] == 0.2);
  // The case's own stop waits for y too: it never comes, and the monitor says so within
  // case_patience corrections, keeping where the measure was met.
  const int met = n;
  while (m.state() == SolveMonitor::State::converged && n < 1000) m.feed(noise(++n));
  CHECK(m.state() == SolveMonitor::State::case_stuck);
  CHECK(n == met + 50);
  CHECK(m.converged_at() == met);
  // Watching x alone (as the case does for one material), its own stop comes: no verdict.
  SolveMonitor::Options x_alone = options();
  x_alone.case_watches = {true, false};
  x_alone.case_tolerance = 1e-10;
  SolveMonitor mx(x_alone);
  for (n = 1; n <= 100; ++n) mx.feed(noise(n));
  CHECK(mx.state() == SolveMonitor::State::converged);
}

TEST_CASE("the solve monitor: stalled and diverging solves are named", "[solve]") {
  SECTION("stalled: the measure has not halved for stall_corrections") {
    SolveMonitor m(options());
    int n = 0;
    while (m.state() == SolveMonitor::State::running && n < 1000) m.feed(correction(++n, 1e-4, 3e-5, 1e-9, 1e-9));
    CHECK(m.state() == SolveMonitor::State::stalled);
    CHECK(n == 51);
    CHECK(m.diagnosis().find("the x displacement's residual has not fallen for 50 corrections") != std::string::npos);
    // A slow but steady solve is not stalled.
    SolveMonitor slow(options());
    for (n = 1; n <= 400; ++n) slow.feed(correction(n, std::pow(0.98, n), 1e-12, 1e-9, 1e-9));
    CHECK(slow.state() == SolveMonitor::State::running);
  }
  SECTION("diverging: the displacement a thousand times what the load gives") {
    SolveMonitor m(options());
    int n = 0;
    while (m.state() == SolveMonitor::State::running && n < 100) {
      ++n;
      m.feed(correction(n, 0.3, 0.3, 1e-9 * std::pow(2.0, n), 0));
    }
    CHECK(m.state() == SolveMonitor::State::diverging);
    CHECK(n == 10);  // 1e-9 * 2^10 > 1e-6
    CHECK(m.diagnosis().find("the displacement grew to a range of") != std::string::npos);
  }
  SECTION("diverging: a residual that is not a number") {
    SolveMonitor m(options());
    m.feed(correction(1, 1.0, 1.0, 1e-9, 1e-9));
    m.feed("GAMG:  Solving for Dx, Initial residual = nan, Final residual = nan, No Iterations 1000\n");
    CHECK(m.state() == SolveMonitor::State::diverging);
    CHECK(m.diagnosis().find("became NaN") != std::string::npos);
  }
}
