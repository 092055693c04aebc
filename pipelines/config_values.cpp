#include "pipelines/config_values.hpp"

#include <cmath>
#include <limits>

namespace grainmesh {

double read_time_limit(const Config& c) {
  if (c.optional_text(kTimeLimitKey) == "none") return std::numeric_limits<double>::infinity();
  const double seconds = c.number(kTimeLimitKey, kDefaultTimeLimitSeconds);
  if (!(seconds > 0.0) || !std::isfinite(seconds))
    c.fail(kTimeLimitKey, "must be a positive number of seconds or none, got " + c.text(kTimeLimitKey));
  return seconds;
}

double positive(const Config& c, const std::string& key) {
  if (!c.has(key)) c.fail(key, "missing (required)");
  const double v = c.number(key);
  if (!(v > 0.0) || !std::isfinite(v)) c.fail(key, "must be positive, got " + c.text(key));
  return v;
}

double positive(const Config& c, const std::string& key, double fallback) {
  const double v = c.number(key, fallback);
  if (!(v > 0.0)) c.fail(key, "must be positive, got " + c.text(key));
  return v;
}

std::string one_of_keys(const Config& c, const std::string& a, const std::string& b) {
  if (c.has(a) && c.has(b)) c.fail(b, "give either " + a + " or " + b + ", not both");
  return c.has(b) ? b : a;
}

}  // namespace grainmesh
