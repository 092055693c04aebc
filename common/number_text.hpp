// Numbers in files other programs read: the shortest text that reads back as the same
// double, and integers, appended to a growing text.
#pragma once

#include <charconv>
#include <string>
#include <string_view>
#include <type_traits>

namespace grainmesh {

inline std::string number_text(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// Appends v (double: shortest round-trip text; integer: decimal) to `out`.
template <typename T>
void append_number(std::string& out, T v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

// A text being written for another program: strings as they are, numbers by append_number.
struct FileText {
  std::string s;
  FileText& operator<<(std::string_view v) {
    s += v;
    return *this;
  }
  template <typename T>
    requires std::is_arithmetic_v<T>
  FileText& operator<<(T v) {
    append_number(s, v);
    return *this;
  }
};

}  // namespace grainmesh
