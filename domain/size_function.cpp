#include "domain/size_function.hpp"

#include <muParser.h>

#include <algorithm>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace grainmesh {

SizeFunction::SizeFunction(std::shared_ptr<const Node> node) : node_(std::move(node)) {
  if (!node_) throw std::invalid_argument("SizeFunction: null node");
}

double SizeFunction::operator()(Vec2 p) const {
  double h = 0.0;
  node_->eval({&p, 1}, {&h, 1});
  return h;
}

namespace {

struct Constant final : SizeFunction::Node {
  double value;
  void eval(std::span<const Vec2>, std::span<double> out) const override {
    std::fill(out.begin(), out.end(), value);
  }
  double constant_value() const override { return value; }
  std::string describe() const override { return to_text(value, 9); }
};

// muparser keeps the variables it reads by address and its evaluation stack inside the
// parser object, so each batch builds its own parser: thread-safe, and the parse costs
// microseconds against batches of thousands of points.
struct Expression final : SizeFunction::Node {
  std::string text;

  struct Bound {
    mu::Parser parser;
    double x = 0.0, y = 0.0;
    explicit Bound(const std::string& text) {
      parser.DefineVar("x", &x);
      parser.DefineVar("y", &y);
      parser.SetExpr(text);
    }
  };

  void eval(std::span<const Vec2> p, std::span<double> out) const override {
    Bound b(text);
    for (std::size_t i = 0; i < p.size(); ++i) {
      b.x = p[i].x;
      b.y = p[i].y;
      out[i] = b.parser.Eval();
    }
  }
  std::string describe() const override { return text; }
};

struct Minimum final : SizeFunction::Node {
  std::vector<SizeFunction> parts;
  void eval(std::span<const Vec2> p, std::span<double> out) const override {
    parts.front().eval(p, out);
    std::vector<double> tmp(p.size());
    for (std::size_t k = 1; k < parts.size(); ++k) {
      parts[k].eval(p, tmp);
      for (std::size_t i = 0; i < p.size(); ++i) out[i] = std::min(out[i], tmp[i]);
    }
  }
  double constant_value() const override {
    double v = std::numeric_limits<double>::infinity();
    for (const auto& f : parts) {
      if (!f.is_constant()) return std::numeric_limits<double>::quiet_NaN();
      v = std::min(v, f(Vec2{}));
    }
    return v;
  }
  std::string describe() const override {
    std::string s = "min(";
    for (std::size_t k = 0; k < parts.size(); ++k) s += (k ? ", " : "") + parts[k].describe();
    return s + ")";
  }
};

}  // namespace

SizeFunction constant_size(double value) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw ConfigError("size function: constant must be positive and finite, got " + to_text(value, 9));
  auto n = std::make_shared<Constant>();
  n->value = value;
  return SizeFunction(std::move(n));
}

SizeFunction expression_size(const std::string& expression, const std::string& what) {
  auto n = std::make_shared<Expression>();
  n->text = expression;
  try {
    Expression::Bound b(expression);
    b.parser.Eval();  // muparser parses lazily: force it so syntax errors surface here
  } catch (const mu::Parser::exception_type& e) {
    throw ConfigError(what + ": cannot read size expression '" + expression + "': " + e.GetMsg());
  }
  return SizeFunction(std::move(n));
}

SizeFunction minimum_size(std::vector<SizeFunction> parts) {
  if (parts.empty()) throw ConfigError("size function: minimum of nothing");
  if (parts.size() == 1) return parts.front();
  auto n = std::make_shared<Minimum>();
  n->parts = std::move(parts);
  return SizeFunction(std::move(n));
}

}  // namespace grainmesh
