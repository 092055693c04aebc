// nlohmann's JSON errors as a line for users: "[json.exception.parse_error.101] parse
// error at line 1, column 1: syntax error ..." becomes "not JSON: syntax error at line 1,
// column 1 ...", other errors lose their bracketed tag.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace grainmesh {

inline std::string json_error_text(const nlohmann::json::exception& e) {
  std::string text = e.what();
  if (const auto tag = text.find("] "); text.rfind("[json.exception.", 0) == 0 && tag != std::string::npos)
    text.erase(0, tag + 2);
  if (dynamic_cast<const nlohmann::json::parse_error*>(&e)) {
    if (text.rfind("parse error ", 0) == 0) text.erase(0, 12);
    return "not JSON (" + text + ")";
  }
  return text;
}

}  // namespace grainmesh
