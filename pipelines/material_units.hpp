// Moduli and expansions given in the wrong unit are the commonest slip in a config: E in
// GPa (700 for WC) reads as 700 Pa, alpha in ppm/K (5.2) as 5.2 per kelvin. A value no
// solid has is refused, naming the likely slip, unless the user confirms the unit with
// units.checked = true.
#pragma once

#include <string>

#include "pipelines/config.hpp"

namespace grainmesh {

inline constexpr const char* kUnitsCheckedKey = "units.checked";

// E (Pa) of config key `key`: below 1 MPa is refused (ConfigError naming the key) unless
// units.checked.
void check_modulus_unit(const Config& c, const std::string& key, double E);
// alpha (1/K) of config key `key`: above 1e-3 /K is refused unless units.checked.
void check_expansion_unit(const Config& c, const std::string& key, double alpha);

}  // namespace grainmesh
