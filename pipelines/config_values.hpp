// Values many stages' keys share, read from a config: the run's time limit, positive
// numbers, one key of two names. Each throws ConfigError naming the key.
#pragma once

#include <string>

#include "pipelines/config.hpp"

namespace grainmesh {

// The run's wall-clock guard: key limits.seconds, seconds > 0 or "none"; 6 hours unless
// given. Every command that meshes or tessellates reads it and reports it.
inline constexpr const char* kTimeLimitKey = "limits.seconds";
inline constexpr double kDefaultTimeLimitSeconds = 6 * 3600.0;
// Its value (infinity for "none"). Throws ConfigError naming the key.
double read_time_limit(const Config& config);

// A key's value that must be a positive number (ConfigError naming the key otherwise):
// required, or `fallback` when the key is not given.
double positive(const Config& c, const std::string& key);
double positive(const Config& c, const std::string& key, double fallback);
// Of two names for one key (`a`, and the run config's `b`: mesh.size and mesh.h), the one
// the config gives (a when neither); both given fails naming b.
std::string one_of_keys(const Config& config, const std::string& a, const std::string& b);

}  // namespace grainmesh
