#include "grains/feature_size.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>
#include <string>
#include <tuple>

namespace grainmesh {

FeatureSize::FeatureSize(std::vector<SizeSource> sources, double base, double gradient)
    : sources_(std::move(sources)), base_(base), gradient_(gradient) {
  if (sources_.size() < 32) return;  // a plain loop is faster
  Box box;
  finest_ = base_;
  for (const SizeSource& s : sources_) {
    box.extend(s.p);
    finest_ = std::min(finest_, s.h);
  }
  // A source binds only within (base - finest) / gradient of itself; bins a quarter of
  // that let a query stop after the nearest few.
  cell_ = std::max(0.25 * (base_ - finest_) / gradient_, 1e-300);
  lo_ = box.lo;
  nx_ = static_cast<int>(std::min(1024.0, std::floor(box.width() / cell_) + 1));
  ny_ = static_cast<int>(std::min(1024.0, std::floor(box.height() / cell_) + 1));
  cell_ = std::max({cell_, box.width() / nx_, box.height() / ny_});
  std::vector<int> bin(sources_.size());
  start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  least_.assign(static_cast<std::size_t>(nx_) * ny_, base_);
  for (std::size_t k = 0; k < sources_.size(); ++k) {
    const int x = std::min(nx_ - 1, static_cast<int>((sources_[k].p.x - lo_.x) / cell_));
    const int y = std::min(ny_ - 1, static_cast<int>((sources_[k].p.y - lo_.y) / cell_));
    bin[k] = y * nx_ + x;
    ++start_[bin[k] + 1];
    least_[bin[k]] = std::min(least_[bin[k]], sources_[k].h);
  }
  for (std::size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
  order_.resize(sources_.size());
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (std::size_t k = 0; k < sources_.size(); ++k) order_[fill[bin[k]]++] = static_cast<int>(k);
  // The least size anywhere in each bin: most queries lie where no source binds, and
  // this answers them at once.
  floor_.assign(static_cast<std::size_t>(nx_) * ny_, base_);
  for (const SizeSource& s : sources_) {
    const double reach = (base_ - s.h) / gradient_;
    const int x0 = std::max(0, static_cast<int>(std::floor((s.p.x - reach - lo_.x) / cell_)));
    const int x1 = std::min(nx_ - 1, static_cast<int>(std::floor((s.p.x + reach - lo_.x) / cell_)));
    const int y0 = std::max(0, static_cast<int>(std::floor((s.p.y - reach - lo_.y) / cell_)));
    const int y1 = std::min(ny_ - 1, static_cast<int>(std::floor((s.p.y + reach - lo_.y) / cell_)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double dx = std::max({0.0, lo_.x + x * cell_ - s.p.x, s.p.x - (lo_.x + (x + 1) * cell_)});
        const double dy = std::max({0.0, lo_.y + y * cell_ - s.p.y, s.p.y - (lo_.y + (y + 1) * cell_)});
        double& f = floor_[static_cast<std::size_t>(y) * nx_ + x];
        f = std::min(f, s.h + gradient_ * std::sqrt(dx * dx + dy * dy));
      }
  }
}

double FeatureSize::at(Vec2 x, double cap) const {
  double h = std::min(cap, base_);
  if (nx_ == 0) {
    for (const SizeSource& s : sources_) h = std::min(h, s.h + gradient_ * norm(x - s.p));
    return h;
  }
  // Rings of bins around x, nearest first: ring k lies at least (k - 1) cells away, so
  // once finest + gradient (k - 1) cell reaches h nothing further can lower it.
  const double fx = (x.x - lo_.x) / cell_, fy = (x.y - lo_.y) / cell_;
  const int cx = static_cast<int>(std::floor(fx)), cy = static_cast<int>(std::floor(fy));
  if (cx >= 0 && cx < nx_ && cy >= 0 && cy < ny_ && floor_[static_cast<std::size_t>(cy) * nx_ + cx] >= h) return h;
  auto visit = [&](int bx, int by) {
    const int b = by * nx_ + bx;
    // The distance from x to the bin bounds what its sources can give.
    const double dx = std::max({0.0, bx - fx, fx - (bx + 1)}), dy = std::max({0.0, by - fy, fy - (by + 1)});
    if (least_[b] + gradient_ * cell_ * std::sqrt(dx * dx + dy * dy) >= h) return;
    for (int i = start_[b]; i < start_[b + 1]; ++i) {
      const SizeSource& s = sources_[order_[i]];
      h = std::min(h, s.h + gradient_ * norm(x - s.p));
    }
  };
  for (int k = 0;; ++k) {
    if (k > 0 && finest_ + gradient_ * (k - 1) * cell_ >= h) break;
    const int x0 = cx - k, x1 = cx + k, y0 = cy - k, y1 = cy + k;
    for (int by = std::max(0, y0); by <= std::min(ny_ - 1, y1); ++by) {
      if (by == y0 || by == y1) {
        for (int bx = std::max(0, x0); bx <= std::min(nx_ - 1, x1); ++bx) visit(bx, by);
      } else {
        if (x0 >= 0 && x0 < nx_) visit(x0, by);
        if (x1 >= 0 && x1 < nx_) visit(x1, by);
      }
    }
    if (x0 <= 0 && y0 <= 0 && x1 >= nx_ - 1 && y1 >= ny_ - 1) break;  // the whole grid seen
  }
  return h;
}

namespace {

// cos 60 degrees: edges meeting at less than this angle count as a feature.
constexpr double kAcute = 0.5;
// Samples added along one edge where a thin feature asks for more than every `spacing`.
constexpr int kMaxRefinedSamples = 2048;

struct CappedNode final : SizeFunction::Node {
  CappedNode(std::shared_ptr<const FeatureSize> s, double c) : size(std::move(s)), cap(c) {}
  void eval(std::span<const Vec2> p, std::span<double> out) const override {
    for (std::size_t i = 0; i < p.size(); ++i) out[i] = size->at(p[i], cap);
  }
  double constant_value() const override {
    return size->sources() == 0 ? std::min(cap, size->base()) : std::numeric_limits<double>::quiet_NaN();
  }
  std::string describe() const override { return "feature size"; }
  std::shared_ptr<const FeatureSize> size;
  double cap;
};

// Edges (with their periodic images) in a uniform grid, for "nearest edge within R".
class EdgeGrid {
 public:
  EdgeGrid(const Tessellation& t, double cell, double reach) : cell_(cell) {
    lo_ = {-reach, -reach};
    nx_ = std::max(1, static_cast<int>(std::ceil((t.width + 2 * reach) / cell)));
    ny_ = std::max(1, static_cast<int>(std::ceil((t.height + 2 * reach) / cell)));
    bins_.resize(static_cast<std::size_t>(nx_) * ny_);
    const int k = t.periodic ? 1 : 0;
    for (int e = 0; e < static_cast<int>(t.edges.size()); ++e)
      for (int j = -k; j <= k; ++j)
        for (int i = -k; i <= k; ++i) {
          const Vec2 shift{i * t.width, j * t.height};
          const Vec2 a = t.vertices[t.edges[e].v0] + shift, b = t.vertices[t.edges[e].v1] + shift;
          Box box;
          box.extend(a);
          box.extend(b);
          const int x0 = bin_x(box.lo.x), x1 = bin_x(box.hi.x), y0 = bin_y(box.lo.y), y1 = bin_y(box.hi.y);
          if (x1 < 0 || y1 < 0 || x0 >= nx_ || y0 >= ny_) continue;
          segments_.push_back({a, b, e});
          for (int y = std::max(y0, 0); y <= std::min(y1, ny_ - 1); ++y)
            for (int x = std::max(x0, 0); x <= std::min(x1, nx_ - 1); ++x)
              bins_[static_cast<std::size_t>(y) * nx_ + x].push_back(static_cast<int>(segments_.size()) - 1);
        }
  }

  // Distance from p to the nearest edge for which `skip(edge)` is false, at most `reach`.
  template <typename Skip>
  double nearest(Vec2 p, double reach, Skip&& skip) const {
    double best = reach;
    const int x0 = std::max(0, bin_x(p.x - reach)), x1 = std::min(nx_ - 1, bin_x(p.x + reach));
    const int y0 = std::max(0, bin_y(p.y - reach)), y1 = std::min(ny_ - 1, bin_y(p.y + reach));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        for (int s : bins_[static_cast<std::size_t>(y) * nx_ + x]) {
          const Seg& g = segments_[s];
          if (skip(g.edge)) continue;
          best = std::min(best, std::sqrt(segment_distance2(p, g.a, g.b)));
        }
    return best;
  }

 private:
  struct Seg {
    Vec2 a, b;
    int edge;
  };
  int bin_x(double x) const { return static_cast<int>(std::floor((x - lo_.x) / cell_)); }
  int bin_y(double y) const { return static_cast<int>(std::floor((y - lo_.y) / cell_)); }
  double cell_;
  Vec2 lo_;
  int nx_ = 1, ny_ = 1;
  std::vector<Seg> segments_;
  std::vector<std::vector<int>> bins_;
};

// On a periodic cell, the images of the sources that reach across a side, so that the
// field is periodic.
void add_periodic_images(const Tessellation& t, double max_size, double gradient, std::vector<SizeSource>& sources) {
  if (!t.periodic) return;
  const std::size_t n = sources.size();
  for (std::size_t s = 0; s < n; ++s) {
    const double r = (max_size - sources[s].h) / gradient;
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i) {
        if (i == 0 && j == 0) continue;
        const Vec2 q = sources[s].p + Vec2{i * t.width, j * t.height};
        const double dx = std::max({-q.x, 0.0, q.x - t.width}), dy = std::max({-q.y, 0.0, q.y - t.height});
        if (dx * dx + dy * dy < r * r) sources.push_back({q, sources[s].h});
      }
  }
}

}  // namespace

SizeFunction capped_size(std::shared_ptr<const FeatureSize> size, double cap) {
  return SizeFunction(std::make_shared<CappedNode>(std::move(size), cap));
}

std::vector<SizeSource> feature_sources(const Tessellation& t, double spacing, double max_size, double fraction,
                                        double gradient) {
  const double reach = max_size / fraction;  // features wider than this never bind
  const EdgeGrid grid(t, std::max(spacing, reach), reach);
  // A vertex and its periodic partners are one point of the torus.
  std::vector<int> cls(t.vertices.size());
  for (std::size_t v = 0; v < cls.size(); ++v) cls[v] = static_cast<int>(v);
  auto root = [&](int v) {
    while (cls[v] != v) v = cls[v] = cls[cls[v]];
    return v;
  };
  for (const auto* pairs : {&t.partners.x, &t.partners.y})
    for (const auto& [a, b] : *pairs) cls[root(a)] = root(b);
  std::vector<std::vector<int>> incident(t.vertices.size());
  for (int e = 0; e < static_cast<int>(t.edges.size()); ++e) {
    incident[root(t.edges[e].v0)].push_back(e);
    incident[root(t.edges[e].v1)].push_back(e);
  }
  // Cell-side edges are not features of their own on a periodic cell: the grain goes on.
  auto on_side = [&](int e) {
    const TessEdge& ed = t.edges[e];
    return t.periodic && (ed.left < 0 || ed.right < 0);
  };
  std::vector<SizeSource> out;
  auto add = [&](Vec2 p, double lfs) {
    if (fraction * lfs < max_size) out.push_back({p, fraction * lfs});
  };
  std::vector<double> vertex_size(t.vertices.size());  // what each vertex's source wants
  for (int v = 0; v < static_cast<int>(t.vertices.size()); ++v) {
    const auto& mine = incident[root(v)];
    double lfs = grid.nearest(t.vertices[v], reach, [&](int e) {
      return on_side(e) || std::find(mine.begin(), mine.end(), e) != mine.end();
    });
    for (int e : mine)
      if (!on_side(e)) lfs = std::min(lfs, norm(t.vertices[t.edges[e].v1] - t.vertices[t.edges[e].v0]));
    add(t.vertices[v], lfs);
    vertex_size[v] = fraction * lfs;
  }
  for (int e = 0; e < static_cast<int>(t.edges.size()); ++e) {
    if (on_side(e)) continue;
    const TessEdge& ed = t.edges[e];
    const Vec2 a = t.vertices[ed.v0], b = t.vertices[ed.v1];
    const double len = norm(b - a);
    const int r0 = root(ed.v0), r1 = root(ed.v1);
    // Edges meeting this one at its ends do not count: near a junction they come
    // arbitrarily close without making anything thin.
    auto ignored = [&](int f) {
      if (f == e || on_side(f)) return true;
      const int o0 = root(t.edges[f].v0), o1 = root(t.edges[f].v1);
      if (o0 != r0 && o0 != r1 && o1 != r0 && o1 != r1) return false;
      // An edge meeting this one at an acute angle makes a sharp corner, which
      // wants small elements close to it; wider junctions do not.
      const int shared = (o0 == r0 || o1 == r0) ? ed.v0 : ed.v1;
      const Vec2 v = t.vertices[shared];
      const Vec2 mine = (shared == ed.v0 ? b : a) - v;
      const TessEdge& o = t.edges[f];
      Vec2 other = t.vertices[o.v0] == v ? t.vertices[o.v1] - v : t.vertices[o.v0] - v;
      if (!(t.vertices[o.v0] == v || t.vertices[o.v1] == v)) return true;  // meets an image: leave it
      return dot(mine, other) < kAcute * norm(mine) * norm(other);
    };
    auto sample = [&](double s) {
      const Vec2 p = a + s * (b - a);
      const double lfs = grid.nearest(p, reach, ignored);
      add(p, lfs);
      return fraction * lfs;
    };
    // Samples about every `spacing`; where a thin feature wants far smaller elements,
    // more between them, so that the field between two samples (growing by the gradient)
    // stays near what the feature wants.
    const int n = std::max(2, static_cast<int>(std::ceil(len / spacing)));
    std::vector<std::pair<double, double>> at;  // (s, wanted size)
    for (int k = 1; k < n; ++k) at.push_back({static_cast<double>(k) / n, 0.0});
    for (auto& [s, h] : at) h = sample(s);
    // Breadth first, so that the bound on samples, when reached, leaves them spread out.
    std::deque<std::tuple<double, double, double, double>> gaps;  // s0, h0, s1, h1
    gaps.push_back({0.0, at.front().second, at.front().first, at.front().second});
    for (std::size_t k = 0; k + 1 < at.size(); ++k)
      gaps.push_back({at[k].first, at[k].second, at[k + 1].first, at[k + 1].second});
    gaps.push_back({at.back().first, at.back().second, 1.0, at.back().second});
    for (int added = 0; !gaps.empty() && added < kMaxRefinedSamples; gaps.pop_front()) {
      const auto [s0, h0, s1, h1] = gaps.front();
      const double wanted = std::min(h0, h1);
      if (wanted >= max_size || (s1 - s0) * len <= wanted / gradient) continue;
      // Within its own size of an end, the end's vertex source rules (and toward a sharp
      // corner the samples would want ever less).
      if ((s0 == 0.0 && s1 * len <= vertex_size[ed.v0]) || (s1 == 1.0 && (1.0 - s0) * len <= vertex_size[ed.v1]))
        continue;
      const double mid = 0.5 * (s0 + s1);
      const double hm = sample(mid);
      ++added;
      gaps.push_back({s0, s0 == 0.0 ? hm : h0, mid, hm});
      gaps.push_back({mid, hm, s1, s1 == 1.0 ? hm : h1});
    }
  }
  add_periodic_images(t, max_size, gradient, out);
  return out;
}

std::vector<SizeSource> grading_sources(const Tessellation& t, double boundary_size, double junction_size,
                                        const std::vector<double>& phase_size, double max_size, double gradient) {
  std::vector<SizeSource> out;
  const bool boundary = boundary_size > 0.0 && boundary_size < max_size;
  const bool junction = junction_size > 0.0 && junction_size < max_size;
  // Sources half a size apart along a segment: between two, the field rises by at most a
  // quarter size times the gradient.
  auto along = [&](Vec2 a, Vec2 b, double h) {
    const int n = std::max(1, static_cast<int>(std::ceil(2.0 * norm(b - a) / h)));
    for (int k = 0; k <= n; ++k) out.push_back({a + (static_cast<double>(k) / n) * (b - a), h});
  };
  for (const TessEdge& e : t.edges) {
    if (e.left < 0 || e.right < 0) continue;  // a cell side is no grain boundary
    const Vec2 a = t.vertices[e.v0], b = t.vertices[e.v1];
    if (boundary) along(a, b, boundary_size);
    // Where phases of different sizes meet, the coarser grows from the finer's size.
    const double left = phase_size[t.regions[e.left].phase], right = phase_size[t.regions[e.right].phase];
    if (left != right && std::min(left, right) < max_size) along(a, b, std::min(left, right));
    if (junction)
      for (const Vec2 v : {a, b}) out.push_back({v, junction_size});
  }
  // A vertex is a source once per edge it ends; one is enough.
  std::sort(out.begin(), out.end(), [](const SizeSource& x, const SizeSource& y) {
    return std::tie(x.p.x, x.p.y, x.h) < std::tie(y.p.x, y.p.y, y.h);
  });
  out.erase(std::unique(out.begin(), out.end(), [](const SizeSource& x, const SizeSource& y) { return x.p == y.p; }),
            out.end());
  add_periodic_images(t, max_size, gradient, out);
  return out;
}

}  // namespace grainmesh
