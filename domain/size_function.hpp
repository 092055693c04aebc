// Mesh size functions h(x, y) > 0: the relative edge length wanted at each point
// (thesis section 2.2; only ratios matter, the scale comes from h0). The size function is
// an input in its own right, next to the geometry.
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/geometry.hpp"

namespace grainmesh {

class SizeFunction {
 public:
  struct Node {
    virtual ~Node() = default;
    // out[i] = h(p[i]). Implementations must not keep state between calls.
    virtual void eval(std::span<const Vec2> p, std::span<double> out) const = 0;
    // The constant value when h does not depend on position, else NaN.
    virtual double constant_value() const { return std::numeric_limits<double>::quiet_NaN(); }
    virtual std::string describe() const = 0;
  };

  explicit SizeFunction(std::shared_ptr<const Node> node);

  double operator()(Vec2 p) const;
  void eval(std::span<const Vec2> p, std::span<double> out) const { node_->eval(p, out); }
  bool is_constant() const { return !std::isnan(node_->constant_value()); }
  // Text for error messages and reports, e.g. "min(1, 4*sqrt(x^2+y^2)-1)".
  std::string describe() const { return node_->describe(); }

 private:
  std::shared_ptr<const Node> node_;
};

// h = value everywhere (> 0).
SizeFunction constant_size(double value);
// h = a muparser expression in x and y, e.g. "min(4*sqrt(x^2+y^2)-1, 2)" (thesis eq. 3.11).
// Throws ConfigError naming `what` when the expression does not parse. Evaluation is
// thread-safe (each call uses its own parser state).
SizeFunction expression_size(const std::string& expression, const std::string& what);
// h = min(h_1, ..., h_n), n >= 1.
SizeFunction minimum_size(std::vector<SizeFunction> parts);

}  // namespace grainmesh
