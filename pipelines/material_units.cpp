#include "pipelines/material_units.hpp"

#include "common/format.hpp"

namespace grainmesh {

namespace {
constexpr double kLowestModulus = 1e6;      // Pa: gels and soft rubbers lie above
constexpr double kHighestExpansion = 1e-3;  // 1/K: polymers lie below
}  // namespace

void check_modulus_unit(const Config& c, const std::string& key, double E) {
  if (E >= kLowestModulus || c.flag(kUnitsCheckedKey, false)) return;
  c.fail(key, to_text(E) + " Pa is below 1 MPa: E is in Pa (WC " + (E >= 1.0 && E <= 2000.0 ? "700e9, not " + to_text(E) + " (GPa)" : "700e9") +
                  "); if it is meant, set " + kUnitsCheckedKey + " = true");
}

void check_expansion_unit(const Config& c, const std::string& key, double alpha) {
  if (alpha <= kHighestExpansion || c.flag(kUnitsCheckedKey, false)) return;
  c.fail(key, to_text(alpha) + " /K is above 1e-3 /K: alpha is in 1/K (WC 5.2e-6" +
                  (alpha >= 0.1 && alpha <= 100.0 ? ", not " + to_text(alpha) + " (ppm/K)" : std::string()) +
                  "); if it is meant, set " + kUnitsCheckedKey + " = true");
}

}  // namespace grainmesh
