#include "tessellate/image_tessellation.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/periodic_pairs.hpp"
#include "common/predicates.hpp"
#include "common/ring.hpp"
#include "common/spatial_grid.hpp"
#include "tessellate/read_tessellation.hpp"

namespace grainmesh {

namespace {

// Union-find over 0 .. n-1; join_into keeps the second's root as the root.
struct Unions {
  std::vector<int> parent;
  explicit Unions(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  void join_into(int a, int b) { parent[find(a)] = find(b); }
};

// The pixel lattice: pixel (i, j) is index j nx + i; the pairs of side-by-side pixels,
// across the borders when the image wraps round.
struct Pixels {
  int nx = 0, ny = 0;
  bool wrap = false;
  std::size_t count() const { return static_cast<std::size_t>(nx) * ny; }
  std::size_t at(int i, int j) const { return static_cast<std::size_t>(j) * nx + i; }
  template <typename Visit>  // visit(p, q) for each pair of pixels sharing a side
  void for_pairs(Visit&& visit) const {
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if (i + 1 < nx || (wrap && nx > 1)) visit(at(i, j), at((i + 1) % nx, j));
        if (j + 1 < ny || (wrap && ny > 1)) visit(at(i, j), at(i, (j + 1) % ny));
      }
  }
};

// The 4-connected regions of equal key, numbered 0, 1, ... in the order of their first pixel.
std::vector<int> connected(const std::vector<std::uint32_t>& key, const Pixels& px, int* count) {
  Unions u(px.count());
  px.for_pairs([&](std::size_t p, std::size_t q) {
    if (key[p] == key[q]) u.join(static_cast<int>(p), static_cast<int>(q));
  });
  std::vector<int> id(px.count(), -1);
  int n = 0;
  for (std::size_t p = 0; p < px.count(); ++p) {
    const int r = u.find(static_cast<int>(p));
    if (id[r] < 0) id[r] = n++;
    id[p] = id[r];
  }
  *count = n;
  return id;
}

// Grains below `min_pixels` merged, each into the neighbour it shares the most pixel sides
// with (smallest first, ties to the lower id), until none is left; `grain` renumbered,
// `kept` the old number of each new grain (the one the others merged into). Returns how
// many were merged.
int merge_small_grains(std::vector<int>& grain, int& grains, const Pixels& px, int min_pixels, std::vector<int>& kept) {
  Unions u(grains);
  std::vector<long long> size(grains, 0);
  for (int g : grain) ++size[g];
  int merged = 0;
  for (bool progress = true; progress;) {
    progress = false;
    std::map<int, std::map<int, long long>> shared;  // small root -> neighbour root -> sides
    px.for_pairs([&](std::size_t p, std::size_t q) {
      const int a = u.find(grain[p]), b = u.find(grain[q]);
      if (a == b) return;
      if (size[a] < min_pixels) ++shared[a][b];
      if (size[b] < min_pixels) ++shared[b][a];
    });
    std::vector<int> small;
    for (const auto& [g, n] : shared) small.push_back(g);
    std::stable_sort(small.begin(), small.end(), [&](int a, int b) { return size[a] < size[b]; });
    for (int g : small) {
      if (u.find(g) != g || size[g] >= min_pixels) continue;
      int best = -1;
      long long most = 0;
      for (const auto& [n, sides] : shared[g]) {
        const int r = u.find(n);
        if (r != g && (sides > most || (sides == most && r < best))) best = r, most = sides;
      }
      if (best < 0) continue;
      u.join_into(g, best);
      size[best] += size[g];
      ++merged;
      progress = true;
    }
  }
  std::vector<int> number(grains, -1);
  int n = 0;
  kept.clear();
  for (int& g : grain) {
    const int r = u.find(g);
    if (number[r] < 0) number[r] = n++, kept.push_back(r);
    g = number[r];
  }
  grains = n;
  return merged;
}

enum Dir { kE = 0, kN = 1, kW = 2, kS = 3 };
constexpr std::array<int, 4> kDx{1, 0, -1, 0}, kDy{0, 1, 0, -1};
constexpr double kPinchOffset = 0.25;  // pixels: how far a pinch's two corners move apart

// The boundaries on the lattice of pixel corners: vertex (i, j), 0 <= i <= nx, 0 <= j <= ny,
// at (i, j) in pixel units; an edge of it is a boundary where the pieces on its two sides
// differ (the image's border is not one of these: the sides are laid separately).
struct Lattice {
  int nx, ny;
  const std::vector<int>& piece;  // per pixel

  int at(int i, int j) const {
    return i < 0 || j < 0 || i >= nx || j >= ny ? -1 : piece[static_cast<std::size_t>(j) * nx + i];
  }
  // The pieces left and right of the edge leaving (i, j) in direction d.
  std::pair<int, int> sides(int i, int j, int d) const {
    switch (d) {
      case kE:
        return {at(i, j), at(i, j - 1)};
      case kN:
        return {at(i - 1, j), at(i, j)};
      case kW:
        return {at(i - 1, j - 1), at(i - 1, j)};
      default:
        return {at(i, j - 1), at(i - 1, j - 1)};
    }
  }
  bool boundary(int i, int j, int d) const {
    const auto [l, r] = sides(i, j, d);
    return l >= 0 && r >= 0 && l != r;
  }
  int degree(int i, int j) const {
    int n = 0;
    for (int d = 0; d < 4; ++d) n += boundary(i, j, d);
    return n;
  }
  bool on_side(int i, int j) const { return i == 0 || j == 0 || i == nx || j == ny; }
  // A piece touching itself across the corner (i, j): its two diagonal pixels one piece.
  bool pinch(int i, int j) const {
    return !on_side(i, j) && degree(i, j) == 4 && (at(i - 1, j - 1) == at(i, j) || at(i, j - 1) == at(i - 1, j));
  }
  bool junction(int i, int j) const { return on_side(i, j) || (degree(i, j) >= 3 && !pinch(i, j)); }
  // At a pinch, the two pieces apart from the one touching itself keep their corners: the
  // edge leaving in d continues along its partner, at the corner moved toward that pixel.
  int partner(int i, int j, int d) const {
    const bool ll_ur = at(i - 1, j - 1) == at(i, j);
    static constexpr std::array<int, 4> a{kS, kW, kN, kE}, b{kN, kE, kS, kW};
    return ll_ur ? a[d] : b[d];
  }
  Vec2 pinch_corner(int i, int j, int d) const {
    const bool ll_ur = at(i - 1, j - 1) == at(i, j);
    const int q = ll_ur ? (d == kE || d == kS ? 0 : 1) : (d == kE || d == kN ? 2 : 3);
    static constexpr std::array<double, 4> ox{1, -1, 1, -1}, oy{-1, 1, 1, -1};
    return {i + kPinchOffset * ox[q], j + kPinchOffset * oy[q]};
  }
  // The edge's index among the lattice's edges (horizontal ones first), for marking it.
  std::size_t edge(int i, int j, int d) const {
    const std::size_t horizontal = static_cast<std::size_t>(nx) * (ny + 1);
    switch (d) {
      case kE:
        return static_cast<std::size_t>(j) * nx + i;
      case kW:
        return static_cast<std::size_t>(j) * nx + i - 1;
      case kN:
        return horizontal + static_cast<std::size_t>(j) * (nx + 1) + i;
      default:
        return horizontal + static_cast<std::size_t>(j - 1) * (nx + 1) + i;
    }
  }
  std::size_t edges() const { return static_cast<std::size_t>(nx) * (ny + 1) + static_cast<std::size_t>(nx + 1) * ny; }
  long long vertex(int i, int j) const { return static_cast<long long>(j) * (nx + 1) + i; }
};

// A boundary between two junctions (or a closed one), as traced and as kept.
struct Chain {
  std::vector<Vec2> points;       // pixel units, from the first junction to the last
  long long first = 0, last = 0;  // lattice vertices of its ends (equal when closed)
  int left = -1, right = -1;      // pieces
  double tolerance = 0.0;
  std::vector<int> kept;  // indices into points, ascending, ends included
};

std::vector<Chain> trace(const Lattice& L) {
  std::vector<Chain> chains;
  std::vector<char> seen(L.edges(), 0);
  auto walk = [&](int i, int j, int d) {
    Chain c;
    c.first = L.vertex(i, j);
    std::tie(c.left, c.right) = L.sides(i, j, d);
    c.points.push_back({static_cast<double>(i), static_cast<double>(j)});
    for (;;) {
      seen[L.edge(i, j, d)] = 1;
      i += kDx[d], j += kDy[d];
      const int back = (d + 2) % 4;
      if (L.junction(i, j)) break;
      Vec2 here{static_cast<double>(i), static_cast<double>(j)};
      int next = -1;
      if (L.pinch(i, j)) {
        here = L.pinch_corner(i, j, back);
        next = L.partner(i, j, back);
      } else {
        for (int e = 0; e < 4; ++e)
          if (e != back && L.boundary(i, j, e)) next = e;
      }
      if (seen[L.edge(i, j, next)]) break;  // round a closed boundary to where it began
      c.points.push_back(here);
      d = next;
    }
    c.points.push_back({static_cast<double>(i), static_cast<double>(j)});
    c.last = L.vertex(i, j);
    chains.push_back(std::move(c));
  };
  for (int j = 0; j <= L.ny; ++j)
    for (int i = 0; i <= L.nx; ++i)
      if (L.degree(i, j) > 0 && L.junction(i, j))
        for (int d = 0; d < 4; ++d)
          if (L.boundary(i, j, d) && !seen[L.edge(i, j, d)]) walk(i, j, d);
  // What is left are closed boundaries with no junction: each begun at a corner of it that
  // is not a pinch (the end of its first edge found).
  for (int j = 0; j <= L.ny; ++j)
    for (int i = 0; i <= L.nx; ++i)
      if (L.degree(i, j) == 2 && !L.pinch(i, j))
        for (int d = 0; d < 4; ++d)
          if (L.boundary(i, j, d) && !seen[L.edge(i, j, d)]) walk(i, j, d);
  return chains;
}

// Douglas-Peucker on points[a .. b]: marks the points kept between them.
void simplify(const std::vector<Vec2>& pts, int a, int b, double tol, std::vector<char>& keep) {
  std::vector<std::pair<int, int>> todo{{a, b}};
  while (!todo.empty()) {
    const auto [s, e] = todo.back();
    todo.pop_back();
    int far = -1;
    double worst = tol * tol;
    for (int k = s + 1; k < e; ++k) {
      const double d = segment_distance2(pts[k], pts[s], pts[e]);
      if (d > worst) worst = d, far = k;
    }
    if (far < 0) continue;
    keep[far] = 1;
    todo.push_back({s, far});
    todo.push_back({far, e});
  }
}

// The point of points[a .. b] farthest from the chord, strictly between; -1 when none.
int farthest(const std::vector<Vec2>& pts, int a, int b) {
  int far = -1;
  double worst = -1.0;
  for (int k = a + 1; k < b; ++k) {
    const double d = segment_distance2(pts[k], pts[a], pts[b]);
    if (d > worst) worst = d, far = k;
  }
  return far;
}

// The chain's kept points at its tolerance: a closed chain keeps at least three corners,
// one sharing both ends with another chain at least one point between them.
void keep_points(Chain& c, bool shares_ends) {
  const auto& pts = c.points;
  const int n = static_cast<int>(pts.size());
  std::vector<char> keep(n, 0);
  keep[0] = keep[n - 1] = 1;
  if (c.first == c.last) {
    int far = 1;
    for (int k = 1; k < n - 1; ++k)
      if (norm2(pts[k] - pts[0]) > norm2(pts[far] - pts[0])) far = k;
    keep[far] = 1;
    simplify(pts, 0, far, c.tolerance, keep);
    simplify(pts, far, n - 1, c.tolerance, keep);
    if (std::count(keep.begin(), keep.end(), 1) < 4) {
      const int a = farthest(pts, 0, far), b = farthest(pts, far, n - 1);
      const double da = a < 0 ? -1 : segment_distance2(pts[a], pts[0], pts[far]);
      const double db = b < 0 ? -1 : segment_distance2(pts[b], pts[far], pts[n - 1]);
      keep[da >= db ? a : b] = 1;
    }
  } else {
    simplify(pts, 0, n - 1, c.tolerance, keep);
    if (shares_ends && n > 2 && std::count(keep.begin(), keep.end(), 1) == 2) keep[farthest(pts, 0, n - 1)] = 1;
  }
  c.kept.clear();
  for (int k = 0; k < n; ++k)
    if (keep[k]) c.kept.push_back(k);
}

// Whether the kept segments s = pq and t = ru meet anywhere but at an end they share.
bool conflict(Vec2 p, Vec2 q, Vec2 r, Vec2 u) {
  const bool pr = p == r, pu = p == u, qr = q == r, qu = q == u;
  if ((pr && qu) || (pu && qr)) return true;  // the same segment twice
  auto overlaps = [](Vec2 o, Vec2 a, Vec2 b) { return orient2d(o, a, b) == 0 && dot(a - o, b - o) > 0.0; };
  if (pr) return overlaps(p, q, u);
  if (pu) return overlaps(p, q, r);
  if (qr) return overlaps(q, p, u);
  if (qu) return overlaps(q, p, r);
  return segments_touch(p, q, r, u);
}

// Marks the chains whose kept form changes the boundaries' topology: a kept segment
// meeting another, or passing over a kept point of any chain (the area between a segment
// and the points it replaces holds it). Returns whether any was marked.
bool mark_conflicts(const std::vector<Chain>& chains, int nx, int ny, std::vector<char>& bad) {
  struct Segment {
    int chain, a, b;  // kept points a < b of it
  };
  std::vector<Segment> segs;
  for (int c = 0; c < static_cast<int>(chains.size()); ++c)
    for (std::size_t k = 0; k + 1 < chains[c].kept.size(); ++k)
      segs.push_back({c, chains[c].kept[k], chains[c].kept[k + 1]});
  auto end_a = [&](const Segment& s) { return chains[s.chain].points[s.a]; };
  auto end_b = [&](const Segment& s) { return chains[s.chain].points[s.b]; };
  GridFrame frame{.lo = {-1.0, -1.0}, .cell = 16.0, .nx = nx / 16 + 2, .ny = ny / 16 + 2};
  auto cells = [&](std::size_t k, auto emit) {
    const Vec2 p = end_a(segs[k]), q = end_b(segs[k]);
    for (int y = frame.row(std::min(p.y, q.y)); y <= frame.row(std::max(p.y, q.y)); ++y)
      for (int x = frame.column(std::min(p.x, q.x)); x <= frame.column(std::max(p.x, q.x)); ++x)
        emit(frame.index(x, y));
  };
  const CellLists lists(frame.cells(), segs.size(), cells);
  bool any = false;
  auto mark = [&](int c) { any = true, bad[c] = 1; };
  for (std::size_t cell = 0; cell < frame.cells(); ++cell) {
    const auto here = lists[cell];
    for (std::size_t x = 0; x < here.size(); ++x)
      for (std::size_t y = x + 1; y < here.size(); ++y) {
        const Segment &s = segs[here[x]], &t = segs[here[y]];
        if (conflict(end_a(s), end_b(s), end_a(t), end_b(t))) mark(s.chain), mark(t.chain);
      }
  }
  // Kept points inside the area a segment sweeps from the points it replaces.
  for (const Chain& c : chains)
    for (int k : c.kept) {
      const Vec2 p = c.points[k];
      const auto near = lists[frame.index(frame.column(p.x), frame.row(p.y))];
      for (int id : near) {
        const Segment& s = segs[id];
        if (s.b - s.a < 2) continue;
        const Vec2 a = end_a(s), b = end_b(s);
        if (p == a || p == b || p.x < std::min(a.x, b.x) - 1 || p.x > std::max(a.x, b.x) + 1 ||
            p.y < std::min(a.y, b.y) - 1 || p.y > std::max(a.y, b.y) + 1)
          continue;
        const auto& pts = chains[s.chain].points;
        const std::vector<Vec2> swept(pts.begin() + s.a, pts.begin() + s.b + 1);
        if (inside_ring(swept, p)) mark(s.chain);
      }
    }
  return any;
}

// Every chain kept at the tolerance, or finer where that changed the topology: a chain in
// conflict halves its tolerance until none is (at zero each chain is as traced).
void simplify_chains(std::vector<Chain>& chains, double tolerance, int nx, int ny) {
  std::map<std::pair<long long, long long>, int> ends;
  for (const Chain& c : chains) ++ends[std::minmax(c.first, c.last)];
  auto shares = [&](const Chain& c) { return ends[std::minmax(c.first, c.last)] > 1; };
  for (Chain& c : chains) {
    c.tolerance = tolerance;
    keep_points(c, shares(c));
  }
  std::vector<char> bad(chains.size(), 0);
  for (int round = 0; mark_conflicts(chains, nx, ny, bad); ++round) {
    if (round > 40)
      throw GeometryError("the traced boundaries could not be simplified without crossing (a grainmesh bug)");
    for (std::size_t c = 0; c < chains.size(); ++c)
      if (bad[c]) {
        chains[c].tolerance = chains[c].tolerance < 0.05 ? 0.0 : 0.5 * chains[c].tolerance;
        keep_points(chains[c], shares(chains[c]));
        bad[c] = 0;
      }
  }
}

}  // namespace

namespace {

// The phase of each grain from the table, by the label it carries; a label the table does
// not name refused.
std::vector<int> phases_from_table(const std::vector<std::uint32_t>& label, const std::vector<long long>& pixels,
                                   const ImageTessellationOptions& o, bool colour, const std::string& source) {
  std::vector<int> phase(label.size(), -1);
  std::map<std::uint32_t, long long> missing;  // label -> pixels
  for (std::size_t g = 0; g < label.size(); ++g) {
    phase[g] = phase_of_label(o.label_phases, label[g]);
    if (phase[g] < 0) missing[label[g]] += pixels[g];
  }
  if (!missing.empty()) {
    const auto& [first, count] = *missing.begin();
    const std::string name = colour ? "colour " + label_text(first, true) : "label " + std::to_string(first);
    throw UnnamedLabelError(
        source + ": " + name + " (" + std::to_string(count) + " pixels) has no phase in the table" +
        (missing.size() > 1 ? " (nor " + std::to_string(missing.size() - 1) + " other labels)" : ""));
  }
  return phase;
}

}  // namespace

std::string label_text(std::uint32_t label, bool colour) {
  if (!colour) return std::to_string(label);
  static constexpr char kHex[] = "0123456789abcdef";
  std::string s = "#";
  for (int shift = 20; shift >= 0; shift -= 4) s += kHex[(label >> shift) & 0xf];
  return s;
}

Tessellation image_tessellation(const LabelImage& image, const ImageTessellationOptions& o, Rng& rng,
                                const std::string& source) {
  const Pixels px{image.width, image.height, o.periodic};
  const double h = o.pixel_size;
  // Grains: the regions of one label, small ones merged or refused.
  int grains = 0;
  std::vector<int> grain = connected(image.labels, px, &grains);
  std::vector<long long> pixels(grains, 0);
  for (int g : grain) ++pixels[g];
  std::vector<std::uint32_t> label(grains);
  for (std::size_t p = 0; p < grain.size(); ++p) label[grain[p]] = image.labels[p];
  int merged = 0;
  const long long smallest = *std::min_element(pixels.begin(), pixels.end());
  if (smallest < o.min_grain_pixels && grains > 1) {
    if (!o.merge_small) {
      const auto small =
          std::count_if(pixels.begin(), pixels.end(), [&](long long n) { return n < o.min_grain_pixels; });
      const std::size_t p =
          std::find(grain.begin(), grain.end(), std::min_element(pixels.begin(), pixels.end()) - pixels.begin()) -
          grain.begin();
      throw SmallGrainsError(source + ": " + std::to_string(small) + " grain" + (small > 1 ? "s" : "") +
                             " of fewer than " + std::to_string(o.min_grain_pixels) + " pixels (the smallest " +
                             std::to_string(smallest) + (smallest > 1 ? " pixels" : " pixel") + " of " +
                             (image.colour ? "colour " : "label ") + label_text(image.labels[p], image.colour) +
                             " at pixel (" + std::to_string(p % px.nx) + ", " + std::to_string(p / px.nx) +
                             ") from the bottom left)");
    }
    std::vector<int> kept;
    merged = merge_small_grains(grain, grains, px, o.min_grain_pixels, kept);
    std::vector<std::uint32_t> old = std::move(label);
    label.clear();
    for (int g : kept) label.push_back(old[g]);
  }
  if (grains < 2) throw GeometryError(source + ": the image is one grain (one label throughout)");
  std::vector<std::uint32_t> key(grain.size());
  pixels.assign(grains, 0);
  for (std::size_t p = 0; p < grain.size(); ++p) key[p] = static_cast<std::uint32_t>(grain[p]), ++pixels[grain[p]];
  // Pieces: each grain's parts inside the image, the regions of the tessellation.
  int pieces = 0;
  const std::vector<int> piece = connected(key, Pixels{px.nx, px.ny, false}, &pieces);
  std::vector<int> grain_of(pieces);
  for (std::size_t p = 0; p < piece.size(); ++p) grain_of[piece[p]] = grain[p];
  // Boundaries traced and simplified.
  const Lattice lattice{px.nx, px.ny, piece};
  std::vector<Chain> chains = trace(lattice);
  simplify_chains(chains, o.tolerance, px.nx, px.ny);
  const int nx = px.nx, ny = px.ny;
  Tessellation t;
  t.width = nx * h;
  t.height = ny * h;
  t.periodic = o.periodic;
  t.phases = o.phases;
  // Vertices: the lattice corners the boundaries end at and the sides' corners and
  // crossings (a periodic cell's on both its opposite sides), then each boundary's kept
  // points between its ends.
  std::unordered_map<long long, int> vertex_of;
  auto corner = [&](int i, int j) {
    const auto [it, fresh] = vertex_of.emplace(lattice.vertex(i, j), static_cast<int>(t.vertices.size()));
    if (fresh) t.vertices.push_back({i * h, j * h});
    return it->second;
  };
  auto corner_at = [&](long long v) { return corner(static_cast<int>(v % (nx + 1)), static_cast<int>(v / (nx + 1))); };
  for (const Chain& c : chains) {
    int prev = corner_at(c.first);
    for (std::size_t k = 1; k < c.kept.size(); ++k) {
      int v = 0;
      if (k + 1 == c.kept.size()) {
        v = corner_at(c.last);
      } else {
        v = static_cast<int>(t.vertices.size());
        t.vertices.push_back(c.points[c.kept[k]] * h);
      }
      t.edges.push_back({prev, v, c.left, c.right});
      prev = v;
    }
  }
  auto crossings = [&](int n, auto inner, auto across) {
    std::vector<int> at{0, n};
    for (int k = 1; k < n; ++k)
      if (inner(k) || (o.periodic && across(k))) at.push_back(k);
    std::sort(at.begin(), at.end());
    return at;
  };
  const auto bottom = crossings(
      nx, [&](int i) { return lattice.boundary(i, 0, kN); }, [&](int i) { return lattice.boundary(i, ny, kS); });
  const auto top = crossings(
      nx, [&](int i) { return lattice.boundary(i, ny, kS); }, [&](int i) { return lattice.boundary(i, 0, kN); });
  const auto left = crossings(
      ny, [&](int j) { return lattice.boundary(0, j, kE); }, [&](int j) { return lattice.boundary(nx, j, kW); });
  const auto right = crossings(
      ny, [&](int j) { return lattice.boundary(nx, j, kW); }, [&](int j) { return lattice.boundary(0, j, kE); });
  for (std::size_t k = 0; k + 1 < bottom.size(); ++k)
    t.edges.push_back({corner(bottom[k], 0), corner(bottom[k + 1], 0), lattice.at(bottom[k], 0), -1});
  for (std::size_t k = 0; k + 1 < top.size(); ++k)
    t.edges.push_back({corner(top[k + 1], ny), corner(top[k], ny), lattice.at(top[k], ny - 1), -1});
  for (std::size_t k = 0; k + 1 < left.size(); ++k)
    t.edges.push_back({corner(0, left[k + 1]), corner(0, left[k]), lattice.at(0, left[k]), -1});
  for (std::size_t k = 0; k + 1 < right.size(); ++k)
    t.edges.push_back({corner(nx, right[k]), corner(nx, right[k + 1]), lattice.at(nx - 1, right[k]), -1});
  // Regions: the pieces, each ring followed along the edges with the piece on the left
  // (a hole's then turned to run counter-clockwise too, its outer ring first).
  t.regions.resize(pieces);
  std::vector<std::map<int, int>> next(pieces);
  for (const TessEdge& e : t.edges) {
    if (e.left >= 0) next[e.left][e.v0] = e.v1;
    if (e.right >= 0) next[e.right][e.v1] = e.v0;
  }
  for (int r = 0; r < pieces; ++r) {
    std::vector<std::vector<int>> holes;
    while (!next[r].empty()) {
      std::vector<int> ring;
      for (int v = next[r].begin()->first; next[r].count(v) > 0;) {
        ring.push_back(v);
        const int w = next[r][v];
        next[r].erase(v);
        v = w;
      }
      if (polygon_area(ring_points(t.vertices, ring)) > 0.0) {
        if (!t.regions[r].rings.empty())
          throw GeometryError(source + ": a piece with two outer boundaries (a grainmesh bug)");
        t.regions[r].rings.push_back(std::move(ring));
      } else {
        std::reverse(ring.begin(), ring.end());
        holes.push_back(std::move(ring));
      }
    }
    for (auto& ring : holes) t.regions[r].rings.push_back(std::move(ring));
  }
  // Grains: seeds at the pixel of each one's largest piece nearest that piece's centroid;
  // neighbours across every boundary (across the borders when periodic); phases.
  std::vector<long long> piece_pixels(pieces, 0);
  std::vector<Vec2> piece_sum(pieces, Vec2{});
  for (std::size_t p = 0; p < piece.size(); ++p) {
    ++piece_pixels[piece[p]];
    piece_sum[piece[p]] += Vec2{p % nx + 0.5, static_cast<double>(p / nx) + 0.5};
  }
  std::vector<int> largest(grains, -1);
  for (int r = 0; r < pieces; ++r)
    if (largest[grain_of[r]] < 0 || piece_pixels[r] > piece_pixels[largest[grain_of[r]]]) largest[grain_of[r]] = r;
  std::vector<Vec2> seed(grains);
  std::vector<double> nearest(grains, 1e300);
  for (std::size_t p = 0; p < piece.size(); ++p) {
    const int r = piece[p], g = grain_of[r];
    if (largest[g] != r) continue;
    const Vec2 centre{p % nx + 0.5, static_cast<double>(p / nx) + 0.5};
    const double d = norm2(centre - piece_sum[r] / static_cast<double>(piece_pixels[r]));
    if (d < nearest[g]) nearest[g] = d, seed[g] = centre * h;
  }
  std::set<std::pair<int, int>> touching;
  px.for_pairs([&](std::size_t p, std::size_t q) {
    if (grain[p] != grain[q]) touching.insert(std::minmax(grain[p], grain[q]));
  });
  const std::vector<std::vector<int>> neighbours = neighbour_lists(grains, touching);
  std::vector<int> phase;
  if (!o.label_phases.empty()) {
    phase = phases_from_table(label, pixels, o, image.colour, source);
  } else {
    std::vector<double> areas(grains);
    for (int g = 0; g < grains; ++g) areas[g] = static_cast<double>(pixels[g]) * h * h;
    phase = phases_by_rules(areas, neighbours, o.phases, o.arrangement, t.width * t.height, rng);
  }
  for (int g = 0; g < grains; ++g)
    t.grains.push_back(
        Grain{.id = g, .phase = phase[g], .seed = seed[g], .area = 0.0, .neighbours = neighbours[g], .matrix = false});
  double corners = 0.0;
  for (int r = 0; r < pieces; ++r) {
    t.regions[r].grain = grain_of[r];
    t.regions[r].phase = phase[grain_of[r]];
    corners += static_cast<double>(t.regions[r].rings[0].size());
  }
  if (o.periodic) t.partners = pair_by_position(t.vertices, Box{{0.0, 0.0}, {t.width, t.height}});
  t.stats.removed_grains = merged;
  t.stats.edges_per_grain_mean = corners / grains;
  t.stats.neighbours_mean = 2.0 * static_cast<double>(touching.size()) / grains;
  measure_read_tessellation(t, source);
  return t;
}

}  // namespace grainmesh
