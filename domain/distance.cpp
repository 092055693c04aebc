#include "domain/distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.hpp"
#include "domain/polygon.hpp"

namespace grainmesh {

DistanceFunction::DistanceFunction(std::shared_ptr<const Node> node) : node_(std::move(node)) {
  if (!node_) throw std::invalid_argument("DistanceFunction: null node");
}

std::vector<Vec2> DistanceFunction::vertices() const {
  std::vector<Vec2> out;
  node_->vertices(out);
  return out;
}

double DistanceFunction::curvature_size(Vec2 p, double angle, double gradient) const {
  double h = std::numeric_limits<double>::infinity();
  node_->limit_by_curvature(p, angle, gradient, h);
  return h;
}

namespace {

void require_positive(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw GeometryError(std::string(what) + " must be a positive number, got " + std::to_string(v));
}

struct Circle final : DistanceFunction::Node {
  Vec2 c;
  double r;
  double eval(Vec2 p) const override { return norm(p - c) - r; }
  Box bounds() const override { return {{c.x - r, c.y - r}, {c.x + r, c.y + r}}; }
  void limit_by_curvature(Vec2 p, double angle, double gradient, double& h) const override {
    h = std::min(h, angle * r + gradient * std::abs(eval(p)));
  }
};

// The point of the ellipse (x0/e0)^2 + (x1/e1)^2 = 1, e0 >= e1 > 0, nearest to (y0, y1),
// both >= 0. Off the axes it is (r0 y0/(s + r0), y1/(s + 1)) with r0 = (e0/e1)^2, where s is
// the root of G(s) = (r0 z0/(s + r0))^2 + (z1/(s + 1))^2 - 1, z = y/e (Eberly's
// formulation). G is convex and decreasing on the bracket, so Newton's method started at
// its left end, where G >= 0, climbs to the root monotonically without overshooting.
Vec2 ellipse_nearest_first_quadrant(double e0, double e1, double y0, double y1) {
  if (y1 > 0.0) {
    if (y0 > 0.0) {
      const double z0 = y0 / e0, z1 = y1 / e1;
      if (z0 * z0 + z1 * z1 == 1.0) return {y0, y1};
      const double r0 = (e0 / e1) * (e0 / e1);
      const double n0 = r0 * z0;
      double s = z1 - 1.0;
      for (int i = 0; i < 100; ++i) {
        const double a = n0 / (s + r0), b = z1 / (s + 1.0);
        const double g = a * a + b * b - 1.0;
        if (!(g > 0.0)) break;  // at the root, to rounding
        const double dg = -2.0 * (a * a / (s + r0) + b * b / (s + 1.0));
        const double next = s - g / dg;
        if (!(next > s)) break;  // no more progress in floating point
        s = next;
      }
      return {r0 * y0 / (s + r0), y1 / (s + 1.0)};
    }
    return {0.0, e1};  // on the minor axis
  }
  // On the major axis: the nearest point leaves the axis when y0 is close to the centre.
  const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
  if (numer0 < denom0) {
    const double xde0 = numer0 / denom0;
    return {e0 * xde0, e1 * std::sqrt(std::max(0.0, 1.0 - xde0 * xde0))};
  }
  return {e0, 0.0};
}

struct Ellipse final : DistanceFunction::Node {
  Vec2 c;
  double a, b;
  // Nearest point on the ellipse to p, in the frame centred at c, mirrored into x, y >= 0.
  Vec2 nearest(Vec2 p) const {
    const double x = std::abs(p.x - c.x), y = std::abs(p.y - c.y);
    if (a >= b) return ellipse_nearest_first_quadrant(a, b, x, y);
    const Vec2 q = ellipse_nearest_first_quadrant(b, a, y, x);
    return {q.y, q.x};
  }
  double eval(Vec2 p) const override {
    const Vec2 local{std::abs(p.x - c.x), std::abs(p.y - c.y)};
    const double d = norm(nearest(p) - local);
    const double level = (local.x / a) * (local.x / a) + (local.y / b) * (local.y / b);
    return level < 1.0 ? -d : d;
  }
  Box bounds() const override { return {{c.x - a, c.y - b}, {c.x + a, c.y + b}}; }
  void limit_by_curvature(Vec2 p, double angle, double gradient, double& h) const override {
    // Radius of curvature at (a cos t, b sin t) is (a^2 sin^2 t + b^2 cos^2 t)^(3/2) / (a b).
    const Vec2 q = nearest(p);
    const double ct = q.x / a, st = q.y / b;
    const double m = a * a * st * st + b * b * ct * ct;
    const double radius = m * std::sqrt(m) / (a * b);
    h = std::min(h, angle * radius + gradient * std::abs(eval(p)));
  }
};

struct Rectangle final : DistanceFunction::Node {
  Vec2 lo, hi;
  double eval(Vec2 p) const override {
    const double dx = std::max(lo.x - p.x, p.x - hi.x);
    const double dy = std::max(lo.y - p.y, p.y - hi.y);
    if (dx <= 0.0 && dy <= 0.0) return std::max(dx, dy);
    return std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
  }
  Box bounds() const override { return {lo, hi}; }
  void vertices(std::vector<Vec2>& out) const override {
    out.insert(out.end(), {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}});
  }
};

struct Polygon final : DistanceFunction::Node {
  PolygonRings rings;
  PolygonDistance distance;
  explicit Polygon(PolygonRings r) : rings(std::move(r)), distance(rings) {}
  double eval(Vec2 p) const override { return distance(p); }
  Box bounds() const override { return distance.bounds(); }
  void vertices(std::vector<Vec2>& out) const override {
    for (const auto& ring : rings) out.insert(out.end(), ring.begin(), ring.end());
  }
};

// min (union, eq. 3.3) or max (intersection, eq. 3.8) of several distances.
struct Extremum final : DistanceFunction::Node {
  std::vector<DistanceFunction> parts;
  bool intersection = false;
  double eval(Vec2 p) const override {
    double d = parts.front()(p);
    for (std::size_t i = 1; i < parts.size(); ++i) d = intersection ? std::max(d, parts[i](p)) : std::min(d, parts[i](p));
    return d;
  }
  Box bounds() const override {
    Box b = parts.front().bounds();
    for (const auto& f : parts) {
      if (intersection) b = grainmesh::intersection(b, f.bounds());
      else b.extend(f.bounds());
    }
    return b;
  }
  void vertices(std::vector<Vec2>& out) const override {
    for (const auto& f : parts) f.node()->vertices(out);
  }
  void limit_by_curvature(Vec2 p, double angle, double gradient, double& h) const override {
    for (const auto& f : parts) f.node()->limit_by_curvature(p, angle, gradient, h);
  }
};

struct Difference final : DistanceFunction::Node {
  DistanceFunction a, b;
  Difference(DistanceFunction a_, DistanceFunction b_) : a(std::move(a_)), b(std::move(b_)) {}
  double eval(Vec2 p) const override { return std::max(a(p), -b(p)); }
  Box bounds() const override { return a.bounds(); }
  void vertices(std::vector<Vec2>& out) const override {
    a.node()->vertices(out);
    b.node()->vertices(out);
  }
  void limit_by_curvature(Vec2 p, double angle, double gradient, double& h) const override {
    a.node()->limit_by_curvature(p, angle, gradient, h);
    b.node()->limit_by_curvature(p, angle, gradient, h);
  }
};

struct Translation final : DistanceFunction::Node {
  DistanceFunction d;
  Vec2 offset;
  Translation(DistanceFunction d_, Vec2 o) : d(std::move(d_)), offset(o) {}
  double eval(Vec2 p) const override { return d(p - offset); }
  Box bounds() const override {
    const Box b = d.bounds();
    return {b.lo + offset, b.hi + offset};
  }
  void vertices(std::vector<Vec2>& out) const override {
    const std::size_t first = out.size();
    d.node()->vertices(out);
    for (std::size_t i = first; i < out.size(); ++i) out[i] += offset;
  }
  void limit_by_curvature(Vec2 p, double angle, double gradient, double& h) const override {
    d.node()->limit_by_curvature(p - offset, angle, gradient, h);
  }
};

}  // namespace

DistanceFunction circle(Vec2 centre, double radius) {
  require_positive(radius, "circle radius");
  auto n = std::make_shared<Circle>();
  n->c = centre;
  n->r = radius;
  return DistanceFunction(std::move(n));
}

DistanceFunction ellipse(Vec2 centre, double a, double b) {
  require_positive(a, "ellipse semi-axis a");
  require_positive(b, "ellipse semi-axis b");
  auto n = std::make_shared<Ellipse>();
  n->c = centre;
  n->a = a;
  n->b = b;
  return DistanceFunction(std::move(n));
}

DistanceFunction rectangle(Vec2 lo, Vec2 hi) {
  if (!(lo.x < hi.x && lo.y < hi.y) || !is_finite(lo) || !is_finite(hi))
    throw GeometryError("rectangle: need x1 < x2 and y1 < y2");
  auto n = std::make_shared<Rectangle>();
  n->lo = lo;
  n->hi = hi;
  return DistanceFunction(std::move(n));
}

DistanceFunction polygon(std::vector<std::vector<Vec2>> rings) {
  return DistanceFunction(std::make_shared<Polygon>(std::move(rings)));
}

namespace {
DistanceFunction extremum(std::vector<DistanceFunction> parts, bool intersection) {
  if (parts.empty()) throw GeometryError(std::string(intersection ? "intersection" : "union") + ": needs at least one shape");
  if (parts.size() == 1) return parts.front();
  auto n = std::make_shared<Extremum>();
  n->parts = std::move(parts);
  n->intersection = intersection;
  return DistanceFunction(std::move(n));
}
}  // namespace

DistanceFunction unite(std::vector<DistanceFunction> parts) { return extremum(std::move(parts), false); }

DistanceFunction intersect(std::vector<DistanceFunction> parts) { return extremum(std::move(parts), true); }

DistanceFunction subtract(DistanceFunction a, DistanceFunction b) {
  return DistanceFunction(std::make_shared<Difference>(std::move(a), std::move(b)));
}

DistanceFunction translate(DistanceFunction d, Vec2 offset) {
  return DistanceFunction(std::make_shared<Translation>(std::move(d), offset));
}

Vec2 numerical_gradient(const DistanceFunction& d, Vec2 p, double dp, double step) {
  return {(d({p.x + step, p.y}) - dp) / step, (d({p.x, p.y + step}) - dp) / step};
}

Vec2 project_to_zero(const DistanceFunction& d, Vec2 p, double step, double tolerance,
                     int max_steps) {
  for (int k = 0; k < max_steps; ++k) {
    const double dp = d(p);
    if (std::abs(dp) <= tolerance) break;
    const Vec2 g = numerical_gradient(d, p, dp, step);
    const double g2 = norm2(g);
    if (!(g2 > 0.0)) break;  // flat spot: no direction to move in
    p -= (dp / g2) * g;
  }
  return p;
}

}  // namespace grainmesh
