#include "domain/shape_parser.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "common/errors.hpp"

namespace grainmesh {
namespace {

// Recursive-descent parser over one line of text.
class Parser {
 public:
  Parser(std::string_view text, const std::string& what) : s_(text), what_(what) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw ConfigError(what_ + ": " + message + " at column " + std::to_string(pos_ + 1) + " in '" +
                      std::string(s_) + "'");
  }

  void skip_space() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool at_end() {
    skip_space();
    return pos_ >= s_.size();
  }
  bool peek(char c) {
    skip_space();
    return pos_ < s_.size() && s_[pos_] == c;
  }
  void expect(char c) {
    if (!peek(c)) fail(std::string("expected '") + c + "'");
    ++pos_;
  }
  bool accept(char c) {
    if (!peek(c)) return false;
    ++pos_;
    return true;
  }

  double number() {
    skip_space();
    const char* first = s_.data() + pos_;
    const char* last = s_.data() + s_.size();
    if (first < last && *first == '+') ++first;
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || !std::isfinite(v)) fail("expected a number");
    pos_ = static_cast<std::size_t>(ptr - s_.data());
    return v;
  }

  std::string identifier() {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < s_.size() && (std::isalpha(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_')) ++pos_;
    if (start == pos_) fail("expected a shape name");
    return std::string(s_.substr(start, pos_ - start));
  }

  Vec2 point() {
    const double x = number();
    const double y = number();
    return {x, y};
  }

  std::vector<Vec2> point_list() {
    std::vector<Vec2> pts{point()};
    while (accept(',')) pts.push_back(point());
    return pts;
  }

  DistanceFunction shape() {
    const std::size_t start = pos_;
    const std::string name = identifier();
    expect('(');
    try {
      DistanceFunction d = shape_body(name);
      expect(')');
      return d;
    } catch (const GeometryError& e) {
      pos_ = start;
      throw GeometryError(what_ + ": " + e.what());
    }
  }

 private:
  DistanceFunction shape_body(const std::string& name) {
    auto numbers = [&](int n) {
      std::vector<double> v{number()};
      for (int i = 1; i < n; ++i) {
        expect(',');
        v.push_back(number());
      }
      return v;
    };
    auto shapes = [&] {
      std::vector<DistanceFunction> v{shape()};
      while (accept(',')) v.push_back(shape());
      return v;
    };
    if (name == "circle") {
      const auto v = numbers(3);
      return circle({v[0], v[1]}, v[2]);
    }
    if (name == "ellipse") {
      const auto v = numbers(4);
      return ellipse({v[0], v[1]}, v[2], v[3]);
    }
    if (name == "rectangle") {
      const auto v = numbers(4);
      return rectangle({v[0], v[1]}, {v[2], v[3]});
    }
    if (name == "polygon") {
      std::vector<std::vector<Vec2>> rings{point_list()};
      while (accept(';')) rings.push_back(point_list());
      return polygon(std::move(rings));
    }
    if (name == "union") return unite(shapes());
    if (name == "intersection") return intersect(shapes());
    if (name == "difference") {
      auto a = shape();
      expect(',');
      auto b = shape();
      return subtract(std::move(a), std::move(b));
    }
    if (name == "translate") {
      const auto v = numbers(2);
      expect(',');
      return translate(shape(), {v[0], v[1]});
    }
    fail("unknown shape '" + name +
         "' (known: circle, ellipse, rectangle, polygon, union, difference, intersection, translate)");
  }

  std::string_view s_;
  const std::string& what_;
  std::size_t pos_ = 0;

};

}  // namespace

DistanceFunction parse_shape(std::string_view text, const std::string& what) {
  Parser p(text, what);
  if (p.at_end()) p.fail("empty shape");
  DistanceFunction d = p.shape();
  if (!p.at_end()) p.fail("unexpected text after the shape");
  return d;
}

std::vector<Vec2> parse_point_list(std::string_view text, const std::string& what) {
  Parser p(text, what);
  if (p.at_end()) return {};
  auto pts = p.point_list();
  if (!p.at_end()) p.fail("expected ',' between points");
  return pts;
}

std::vector<double> parse_numbers(std::string_view text, std::size_t count, const std::string& what) {
  Parser p(text, what);
  std::vector<double> v;
  while (!p.at_end()) v.push_back(p.number());
  if (v.size() != count)
    throw ConfigError(what + ": expected " + std::to_string(count) + " numbers, got " +
                      std::to_string(v.size()) + " in '" + std::string(text) + "'");
  return v;
}

}  // namespace grainmesh
