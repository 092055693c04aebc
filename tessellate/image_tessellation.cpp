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
#include "tessellate/image_boundaries.hpp"
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

// The image's grains: its 4-connected regions of one label (across the borders when
// periodic), those below o.min_grain_pixels refused or merged; each pixel's grain, each
// grain's label, how many were merged.
struct ImageGrains {
  std::vector<int> grain;
  int grains = 0;
  std::vector<std::uint32_t> label;
  int merged = 0;
};
ImageGrains image_grains(const LabelImage& image, const Pixels& px, const ImageTessellationOptions& o,
                         const std::string& source) {
  ImageGrains out;
  int& grains = out.grains;
  std::vector<int>& grain = out.grain;
  std::vector<std::uint32_t>& label = out.label;
  int& merged = out.merged;
  grain = connected(image.labels, px, &grains);
  std::vector<long long> pixels(grains, 0);
  for (int g : grain) ++pixels[g];
  label.assign(grains, 0);
  for (std::size_t p = 0; p < grain.size(); ++p) label[grain[p]] = image.labels[p];
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
  return out;
}

// The boundaries as the tessellation's vertices and edges: the lattice corners the chains
// end at and the sides' corners and crossings (a periodic cell's on both its opposite
// sides), then each chain's kept points between its ends; `h` the pixel size.
void add_boundaries(Tessellation& t, const Lattice& lattice, const std::vector<Chain>& chains, bool periodic,
                    double h) {
  const int nx = lattice.nx, ny = lattice.ny;
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
      if (inner(k) || (periodic && across(k))) at.push_back(k);
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
}

// The pieces' rings, each followed along the edges with the piece on the left (a hole's
// then turned to run counter-clockwise too, its outer ring first).
void add_rings(Tessellation& t, int pieces, const std::string& source) {
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
}

// Each grain's seed: the pixel of its largest piece nearest that piece's centroid.
std::vector<Vec2> grain_seeds(const std::vector<int>& piece, const std::vector<int>& grain_of, int grains, int pieces,
                              int nx, double h) {
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
  return seed;
}

Tessellation image_tessellation(const LabelImage& image, const ImageTessellationOptions& o, Rng& rng,
                                const std::string& source) {
  const Pixels px{image.width, image.height, o.periodic};
  const double h = o.pixel_size;
  // Grains: the regions of one label, small ones merged or refused.
  ImageGrains ig = image_grains(image, px, o, source);
  const int grains = ig.grains;
  const std::vector<int>& grain = ig.grain;
  const std::vector<std::uint32_t>& label = ig.label;
  if (grains < 2) throw GeometryError(source + ": the image is one grain (one label throughout)");
  std::vector<std::uint32_t> key(grain.size());
  std::vector<long long> pixels(grains, 0);
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
  add_boundaries(t, lattice, chains, o.periodic, h);
  t.regions.resize(pieces);
  add_rings(t, pieces, source);
  // Grains: seeds; neighbours across every boundary (across the borders when periodic); phases.
  const std::vector<Vec2> seed = grain_seeds(piece, grain_of, grains, pieces, px.nx, h);
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
  t.stats.removed_grains = ig.merged;
  t.stats.edges_per_grain_mean = corners / grains;
  t.stats.neighbours_mean = 2.0 * static_cast<double>(touching.size()) / grains;
  measure_read_tessellation(t, source);
  return t;
}

}  // namespace grainmesh
