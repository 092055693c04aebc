// Property test: many random microstructures, each tessellated and meshed through the
// same readers `grainmesh run` uses, and each mesh put through the conformity checker.
// Each mesh must also keep the quality bound of the mesh stage (tests/mesh/corner_bound.hpp).
// Every realisation is a config text; a failure prints it, so
//   grainmesh run FAILED.ini -o OUT
// replays it. The realisations cover 1 to 500 grains, aspect ratios 1:10 to 10:1, both
// phase modes, every arrangement, phase fractions down to 1 % and up to 99 %, Voronoi and
// Laguerre, Lloyd or not, regularised or not, periodic or not.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <cstdio>
#include <sstream>
#include <string>

#include "common/errors.hpp"
#include "helpers.hpp"
#include "property/realise.hpp"

using namespace grainmesh;

namespace {

// Realisations per test case (there are kCases). Fewer in the sanitizer build, where
// the point is memory and undefined behaviour, not coverage of shapes.
#ifdef GRAINMESH_SANITIZED
constexpr int kPerCase = 3;
#else
constexpr int kPerCase = 84;
#endif
constexpr int kCases = 6;  // the test cases at the end
#ifndef GRAINMESH_SANITIZED
static_assert(kCases * kPerCase >= 500, "the issue asks for at least 500 realisations");
#endif
// The corner bound's value away from sharp corners on these cells (0.6 on the hostile
// and Poisson-Voronoi cases): among the 540 cells it was measured on, unregularised
// Laguerre ones with edges a millionth of the cell long, the worst triangle away from a
// sharp corner has q 0.598.
constexpr double kPlainBound = 0.55;

std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", v);
  return s;
}

// The config of realisation `index`: the discrete choices cycle through every
// combination, the continuous ones are drawn from a stream seeded by the index.
std::string realisation(int index) {
  Rng rng(0x9e3779b97f4a7c15ULL ^ static_cast<std::uint64_t>(index) * 0x2545f4914f6cdd1dULL);
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<std::uint64_t>(n)); };
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, uniform01(rng)); };

  const bool binder = index % 2 == 1;
  const bool periodic = (index / 2) % 2 == 0;
  const char* arrangement = std::array{"random", "dispersed", "clustered"}[(index / 4) % 3];
  const bool regularised = (index / 12) % 2 == 0;
  const bool laguerre = (index / 24) % 2 == 1;
  const int lloyd = (index / 48) % 2 == 0 ? 0 : 1 + pick(5);

  const int grains = std::clamp(static_cast<int>(std::lround(log_uniform(1, 500))), 1, 500);
  const double aspect = log_uniform(0.1, 10.0);
  // The first phase's fraction: the extremes often, anything between otherwise. In binder
  // mode it is the matrix.
  const double extremes[] = {0.01, 0.99, 0.02, 0.95};
  double fraction = pick(3) == 0 ? extremes[pick(4)] : 0.05 + 0.9 * uniform01(rng);
  const bool three_phases = !binder && pick(4) == 0;
  // A binder of a few per cent is meshed with two elements across its thinnest layers:
  // millions of triangles at 500 grains, half a million at 36 grains and 1 % (26 s). Such
  // cells stay small here; tests/grains' binder tests take the thin layers further.
  const int cell_grains = binder && fraction < 0.05 ? std::min(grains, 12) : grains;

  std::ostringstream ini;
  ini << "[domain]\nwidth = " << number(std::sqrt(aspect)) << "\nheight = " << number(1 / std::sqrt(aspect))
      << "\nperiodic = " << (periodic ? "true" : "false") << "\n";
  ini << "[tessellation]\ngrains = " << cell_grains << "\nseed = " << 1000 + index << "\nlloyd_iterations = " << lloyd
      << "\nsize_cv = " << (laguerre ? number(0.2 + 0.6 * uniform01(rng)) : "0")
      << "\nmin_edge = " << (regularised ? "0.1" : "0") << "\nphase_mode = " << (binder ? "binder" : "grain")
      << "\narrangement = " << arrangement << "\n";
  if (binder) ini << "matrix_phase = matrix\n";
  ini << "[phase." << (binder ? "matrix" : "first") << "]\nfraction = " << number(fraction) << "\nE = 300e9\nnu = 0.2\n";
  if (three_phases) ini << "[phase.second]\nfraction = " << number((1 - fraction) / 2) << "\nE = 500e9\nnu = 0.25\n";
  ini << "[phase.hard]\nfraction = rest\nE = 800e9\nnu = 0.1\n";
  ini << "[mesh]\ntriangles_per_grain = " << 20 + pick(30) << "\nthreads = 1\nseed = " << index << "\n";
  return ini.str();
}

// Empty, or what went wrong with one realisation.
std::string check_realisation(const std::string& ini) {
  try {
    return test::mesh_problem(test::realise(ini), kPlainBound);
  } catch (const std::exception& e) {
    return e.what();
  }
}

void check_cases(int which) {
  REQUIRE(which < kCases);
  int failures = 0;
  for (int k = 0; k < kPerCase; ++k) {
    const int index = which * kPerCase + k;
    const std::string ini = realisation(index);
    const auto t0 = std::chrono::steady_clock::now();
    const std::string problem = check_realisation(ini);
    if (const char* dir = std::getenv("GRAINMESH_PROPERTY_DUMP")) {
      std::ofstream(std::string(dir) + "/realisation-" + std::to_string(index) + ".ini") << ini;
      std::fprintf(stderr, "realisation %d: %.3f s %s\n", index,
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), problem.c_str());
    }
    if (!problem.empty()) {
      ++failures;
      UNSCOPED_INFO("realisation " << index << " failed: " << problem << "\nreplay with grainmesh run on:\n" << ini);
    }
  }
  CHECK(failures == 0);
}

}  // namespace

TEST_CASE("random realisations 1 of 6 mesh and conform", "[property]") { check_cases(0); }
TEST_CASE("random realisations 2 of 6 mesh and conform", "[property]") { check_cases(1); }
TEST_CASE("random realisations 3 of 6 mesh and conform", "[property]") { check_cases(2); }
TEST_CASE("random realisations 4 of 6 mesh and conform", "[property]") { check_cases(3); }
TEST_CASE("random realisations 5 of 6 mesh and conform", "[property]") { check_cases(4); }
TEST_CASE("random realisations 6 of 6 mesh and conform", "[property]") { check_cases(5); }
