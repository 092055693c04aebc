// Text as messages and reports print it: numbers and points; and text with its blanks trimmed.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "common/geometry.hpp"

namespace grainmesh {

// Up to `digits` significant digits; NaN as "NaN" (printf would say "-nan" or "nan").
inline std::string to_text(double v, int digits = 6) {
  if (std::isnan(v)) return "NaN";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// "(x, y)"
inline std::string to_text(Vec2 p, int digits = 6) {
  std::string s("(");  // appends, not "(" + ...: GCC 12 warns wrongly on the latter (bug 105651)
  return s.append(to_text(p.x, digits)).append(", ").append(to_text(p.y, digits)).append(")");
}

// `s` without its leading and trailing blanks (spaces and tabs).
inline std::string trimmed(std::string s) {
  s.erase(0, s.find_first_not_of(" \t"));
  s.erase(s.find_last_not_of(" \t") + 1);
  return s;
}

}  // namespace grainmesh
