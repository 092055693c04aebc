#include "grains/feature_size.hpp"

#include <algorithm>
#include <array>
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
  double cell = std::max(0.25 * (base_ - finest_) / gradient_, 1e-300);
  const int nx = static_cast<int>(std::min(1024.0, std::floor(box.width() / cell) + 1));
  const int ny = static_cast<int>(std::min(1024.0, std::floor(box.height() / cell) + 1));
  cell = std::max({cell, box.width() / nx, box.height() / ny});
  grid_ = GridFrame{.lo = box.lo, .cell = cell, .nx = nx, .ny = ny};
  std::vector<std::size_t> bin(sources_.size());
  least_.assign(grid_.cells(), base_);
  for (std::size_t k = 0; k < sources_.size(); ++k) {
    bin[k] = grid_.index(grid_.clamped_column(sources_[k].p.x), grid_.clamped_row(sources_[k].p.y));
    least_[bin[k]] = std::min(least_[bin[k]], sources_[k].h);
  }
  binned_ = CellLists(grid_.cells(), sources_.size(), [&](std::size_t k, auto&& emit) { emit(bin[k]); });
  // The least size anywhere in each bin: most queries lie where no source binds, and
  // this answers them at once.
  floor_.assign(grid_.cells(), base_);
  const Vec2 lo = grid_.lo;
  for (const SizeSource& s : sources_) {
    const double reach = (base_ - s.h) / gradient_;
    const int x0 = std::max(0, grid_.column(s.p.x - reach)), x1 = std::min(nx - 1, grid_.column(s.p.x + reach));
    const int y0 = std::max(0, grid_.row(s.p.y - reach)), y1 = std::min(ny - 1, grid_.row(s.p.y + reach));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double dx = std::max({0.0, lo.x + x * cell - s.p.x, s.p.x - (lo.x + (x + 1) * cell)});
        const double dy = std::max({0.0, lo.y + y * cell - s.p.y, s.p.y - (lo.y + (y + 1) * cell)});
        double& f = floor_[grid_.index(x, y)];
        f = std::min(f, s.h + gradient_ * std::sqrt(dx * dx + dy * dy));
      }
  }
}

double FeatureSize::at(Vec2 x, double cap) const {
  double h = std::min(cap, base_);
  if (grid_.empty()) {
    for (const SizeSource& s : sources_) h = std::min(h, s.h + gradient_ * norm(x - s.p));
    return h;
  }
  // Rings of bins around x, nearest first: ring k lies at least (k - 1) cells away, so
  // once finest + gradient (k - 1) cell reaches h nothing further can lower it.
  const double cell = grid_.cell;
  const double fx = (x.x - grid_.lo.x) / cell, fy = (x.y - grid_.lo.y) / cell;
  const int cx = static_cast<int>(std::floor(fx)), cy = static_cast<int>(std::floor(fy));
  if (grid_.contains(cx, cy) && floor_[grid_.index(cx, cy)] >= h) return h;
  auto visit = [&](int bx, int by) {
    const std::size_t b = grid_.index(bx, by);
    // The distance from x to the bin bounds what its sources can give.
    // (std::max of two: the sanitizer build keeps an initializer list on the stack, 10x slower.)
    const double dx = std::max(0.0, std::max(bx - fx, fx - (bx + 1)));
    const double dy = std::max(0.0, std::max(by - fy, fy - (by + 1)));
    if (least_[b] + gradient_ * cell * std::sqrt(dx * dx + dy * dy) >= h) return;
    for (int k : binned_[b]) h = std::min(h, sources_[k].h + gradient_ * norm(x - sources_[k].p));
  };
  for (int k = 0;; ++k) {
    if (k > 0 && finest_ + gradient_ * (k - 1) * cell >= h) break;
    grid_.for_ring(cx, cy, k, visit);
    if (cx - k <= 0 && cy - k <= 0 && cx + k >= grid_.nx - 1 && cy + k >= grid_.ny - 1) break;  // the whole grid seen
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
  EdgeGrid(const Tessellation& t, double cell, double reach) {
    grid_ = GridFrame{.lo = {-reach, -reach},
                      .cell = cell,
                      .nx = std::max(1, static_cast<int>(std::ceil((t.width + 2 * reach) / cell))),
                      .ny = std::max(1, static_cast<int>(std::ceil((t.height + 2 * reach) / cell)))};
    std::vector<std::array<int, 4>> spans;  // columns x0 .. x1, rows y0 .. y1 of each segment
    const int k = t.periodic ? 1 : 0;
    for (int e = 0; e < static_cast<int>(t.edges.size()); ++e)
      for (int j = -k; j <= k; ++j)
        for (int i = -k; i <= k; ++i) {
          const Vec2 shift{i * t.width, j * t.height};
          const Vec2 a = t.vertices[t.edges[e].v0] + shift, b = t.vertices[t.edges[e].v1] + shift;
          Box box;
          box.extend(a);
          box.extend(b);
          const int x0 = grid_.column(box.lo.x), x1 = grid_.column(box.hi.x);
          const int y0 = grid_.row(box.lo.y), y1 = grid_.row(box.hi.y);
          if (x1 < 0 || y1 < 0 || x0 >= grid_.nx || y0 >= grid_.ny) continue;
          segments_.push_back({a, b, e});
          spans.push_back({std::max(x0, 0), std::min(x1, grid_.nx - 1), std::max(y0, 0), std::min(y1, grid_.ny - 1)});
        }
    bins_ = CellLists(grid_.cells(), segments_.size(), [&](std::size_t s, auto&& emit) {
      for (int y = spans[s][2]; y <= spans[s][3]; ++y)
        for (int x = spans[s][0]; x <= spans[s][1]; ++x) emit(grid_.index(x, y));
    });
  }

  // Distance from p to the nearest edge for which `skip(edge)` is false, at most `reach`.
  template <typename Skip>
  double nearest(Vec2 p, double reach, Skip&& skip) const {
    double best = reach;
    const int x0 = std::max(0, grid_.column(p.x - reach)), x1 = std::min(grid_.nx - 1, grid_.column(p.x + reach));
    const int y0 = std::max(0, grid_.row(p.y - reach)), y1 = std::min(grid_.ny - 1, grid_.row(p.y + reach));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        for (int s : bins_[grid_.index(x, y)]) {
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
  GridFrame grid_;
  std::vector<Seg> segments_;
  CellLists bins_;
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

namespace {

// Sources at a tessellation's features (see feature_sources), in order: one per vertex,
// then each edge's samples.
class FeatureSampler {
 public:
  FeatureSampler(const Tessellation& t, double spacing, double max_size, double fraction, double gradient)
      : t_(t), spacing_(spacing), max_size_(max_size), fraction_(fraction), gradient_(gradient),
        reach_(max_size / fraction), grid_(t, std::max(spacing, reach_), reach_), point_(torus_points(t)),
        incident_(t.vertices.size()) {
    for (int e = 0; e < static_cast<int>(t.edges.size()); ++e) {
      incident_[point_[t.edges[e].v0]].push_back(e);
      incident_[point_[t.edges[e].v1]].push_back(e);
    }
  }

  std::vector<SizeSource> sources() {
    std::vector<double> vertex_size(t_.vertices.size());  // what each vertex's source wants
    for (int v = 0; v < static_cast<int>(t_.vertices.size()); ++v) vertex_size[v] = vertex_source(v);
    for (int e = 0; e < static_cast<int>(t_.edges.size()); ++e)
      if (!on_side(e)) edge_sources(e, vertex_size);
    return std::move(out_);
  }

 private:
  // A vertex and its periodic partners are one point of the torus: its representative.
  static std::vector<int> torus_points(const Tessellation& t) {
    std::vector<int> cls(t.vertices.size());
    for (std::size_t v = 0; v < cls.size(); ++v) cls[v] = static_cast<int>(v);
    auto root = [&](int v) {
      while (cls[v] != v) v = cls[v] = cls[cls[v]];
      return v;
    };
    for (const auto* pairs : {&t.partners.axis[0], &t.partners.axis[1]})
      for (const auto& [a, b] : *pairs) cls[root(a)] = root(b);
    for (int v = 0; v < static_cast<int>(cls.size()); ++v) cls[v] = root(v);
    return cls;
  }

  // Cell-side edges are not features of their own on a periodic cell: the grain goes on.
  bool on_side(int e) const {
    const TessEdge& ed = t_.edges[e];
    return t_.periodic && (ed.left < 0 || ed.right < 0);
  }

  // A source wanting fraction x lfs, when that is below max_size; returns what it wants.
  double add(Vec2 p, double lfs) {
    if (fraction_ * lfs < max_size_) out_.push_back({p, fraction_ * lfs});
    return fraction_ * lfs;
  }

  // Vertex v's source: the nearest edge not ending at v, and v's shortest edge.
  double vertex_source(int v) {
    const auto& mine = incident_[point_[v]];
    double lfs = grid_.nearest(t_.vertices[v], reach_, [&](int e) {
      return on_side(e) || std::find(mine.begin(), mine.end(), e) != mine.end();
    });
    for (int e : mine)
      if (!on_side(e)) lfs = std::min(lfs, norm(t_.vertices[t_.edges[e].v1] - t_.vertices[t_.edges[e].v0]));
    return add(t_.vertices[v], lfs);
  }

  // True when edge f does not count for edge e's samples: e itself, a cell side, or an
  // edge meeting e at an end. Near a junction those come arbitrarily close without making
  // anything thin, unless they meet at an acute angle: a sharp corner wants small elements.
  bool ignored(int e, int f) const {
    const TessEdge& ed = t_.edges[e];
    if (f == e || on_side(f)) return true;
    const int r0 = point_[ed.v0], r1 = point_[ed.v1];
    const int o0 = point_[t_.edges[f].v0], o1 = point_[t_.edges[f].v1];
    if (o0 != r0 && o0 != r1 && o1 != r0 && o1 != r1) return false;
    const int shared = (o0 == r0 || o1 == r0) ? ed.v0 : ed.v1;
    const Vec2 v = t_.vertices[shared];
    const Vec2 mine = t_.vertices[shared == ed.v0 ? ed.v1 : ed.v0] - v;
    const TessEdge& o = t_.edges[f];
    Vec2 other = t_.vertices[o.v0] == v ? t_.vertices[o.v1] - v : t_.vertices[o.v0] - v;
    if (!(t_.vertices[o.v0] == v || t_.vertices[o.v1] == v)) return true;  // meets an image: leave it
    return dot(mine, other) < kAcute * norm(mine) * norm(other);
  }

  // Samples about every `spacing` along edge e; where a thin feature wants far smaller
  // elements, more between them, so that the field between two samples (growing by the
  // gradient) stays near what the feature wants.
  void edge_sources(int e, const std::vector<double>& vertex_size) {
    const TessEdge& ed = t_.edges[e];
    const Vec2 a = t_.vertices[ed.v0], b = t_.vertices[ed.v1];
    const double len = norm(b - a);
    auto sample = [&](double s) {
      const Vec2 p = a + s * (b - a);
      return add(p, grid_.nearest(p, reach_, [&](int f) { return ignored(e, f); }));
    };
    const int n = std::max(2, static_cast<int>(std::ceil(len / spacing_)));
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
      if (wanted >= max_size_ || (s1 - s0) * len <= wanted / gradient_) continue;
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

  const Tessellation& t_;
  const double spacing_, max_size_, fraction_, gradient_;
  const double reach_;  // features wider than this never bind
  const EdgeGrid grid_;
  const std::vector<int> point_;                 // per vertex: its torus point's representative
  std::vector<std::vector<int>> incident_;       // per representative: the edges ending there
  std::vector<SizeSource> out_;
};

}  // namespace

std::vector<SizeSource> feature_sources(const Tessellation& t, double spacing, double max_size, double fraction,
                                        double gradient) {
  std::vector<SizeSource> out = FeatureSampler(t, spacing, max_size, fraction, gradient).sources();
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
