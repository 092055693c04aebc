// Label images in: an image drawn from a known tessellation comes back with the same
// grains, each grain's area within one pixel row of its perimeter, the same neighbours and
// phase fractions within 0.5 %; hand-drawn images hold the cases tracing must get right
// (a grain touching itself at a corner, an island, exact pixel areas at zero tolerance);
// small grains and labels without a phase refused naming the file.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include "common/errors.hpp"
#include "common/ring.hpp"
#include "helpers.hpp"
#include "tessellate/image_tessellation.hpp"
#include "tessellate/label_image.hpp"
#include "tessellate/tessellate.hpp"

using namespace grainmesh;

namespace {

std::vector<Phase> two_phases() {
  return {
      Phase{.name = "WC", .fraction = 0.8, .rest = false, .youngs_modulus = 700e9, .poisson_ratio = 0.2, .alpha = {}},
      Phase{.name = "Co", .fraction = 0.0, .rest = true, .youngs_modulus = 200e9, .poisson_ratio = 0.3, .alpha = {}}};
}

// Pairs of grains and the length of boundary they share, the cell's sides paired across
// when periodic.
std::map<std::pair<int, int>, double> shared_lengths(const Tessellation& t) {
  std::map<std::pair<int, int>, double> out;
  auto add = [&](int a, int b, double length) {
    if (a != b) out[std::minmax(a, b)] += length;
  };
  for (const TessEdge& e : t.edges)
    if (e.left >= 0 && e.right >= 0)
      add(t.regions[e.left].grain, t.regions[e.right].grain, norm(t.vertices[e.v1] - t.vertices[e.v0]));
  if (!t.periodic) return out;
  for (int axis = 0; axis < 2; ++axis) {
    auto along = [&](Vec2 p) { return axis == 0 ? p.y : p.x; };
    auto across = [&](Vec2 p) { return axis == 0 ? p.x : p.y; };
    const double high = axis == 0 ? t.width : t.height;
    std::vector<std::tuple<double, double, int>> low_side, high_side;
    for (const TessEdge& e : t.edges) {
      if (e.right >= 0) continue;
      const Vec2 a = t.vertices[e.v0], b = t.vertices[e.v1];
      if (across(a) != across(b)) continue;
      auto& side = across(a) == 0.0 ? low_side : across(a) == high ? high_side : low_side;
      if (across(a) != 0.0 && across(a) != high) continue;
      side.emplace_back(std::min(along(a), along(b)), std::max(along(a), along(b)), t.regions[e.left].grain);
    }
    for (const auto& [l0, l1, g] : low_side)
      for (const auto& [h0, h1, k] : high_side)
        if (std::min(l1, h1) > std::max(l0, h0)) add(g, k, std::min(l1, h1) - std::max(l0, h0));
  }
  return out;
}

// The smallest distance between two grains' boundaries (their images across a periodic
// cell included).
double gap(const Tessellation& t, int a, int b) {
  auto rings = [&](int g) {
    std::vector<std::vector<Vec2>> out;
    for (const Region& r : t.regions)
      if (r.grain == g)
        for (const auto& ring : r.rings) out.push_back(ring_points(t.vertices, ring));
    return out;
  };
  const auto ra = rings(a), rb = rings(b);
  double best = 1e300;
  const int reach = t.periodic ? 1 : 0;
  for (int sx = -reach; sx <= reach; ++sx)
    for (int sy = -reach; sy <= reach; ++sy)
      for (const auto& p : ra)
        for (const auto& q : rb)
          for (const Vec2& v : p)
            for (std::size_t k = 0; k < q.size(); ++k) {
              const Vec2 shift{sx * t.width, sy * t.height};
              best = std::min(best, std::sqrt(segment_distance2(v + shift, q[k], q[(k + 1) % q.size()])));
            }
  return best;
}

double perimeter(const Tessellation& t, int grain) {
  double length = 0.0;
  for (const Region& r : t.regions)
    if (r.grain == grain)
      for (const auto& ring : r.rings) {
        const auto pts = ring_points(t.vertices, ring);
        for (std::size_t k = 0; k < pts.size(); ++k) length += norm(pts[(k + 1) % pts.size()] - pts[k]);
      }
  return length;
}

LabelImage from_rows(const std::vector<std::vector<std::uint32_t>>& rows_top_down) {
  LabelImage image;
  image.height = static_cast<int>(rows_top_down.size());
  image.width = static_cast<int>(rows_top_down[0].size());
  for (int j = image.height - 1; j >= 0; --j)
    for (std::uint32_t v : rows_top_down[j]) image.labels.push_back(v);
  return image;
}

ImageTessellationOptions plain_options() {
  ImageTessellationOptions o;
  o.pixel_size = 0.5;
  o.tolerance = 0.0;
  o.min_grain_pixels = 1;
  o.phases = two_phases();
  return o;
}

}  // namespace

TEST_CASE("A label image drawn from a known tessellation comes back with its grains, areas, neighbours and phases",
          "[tessellate][image]") {
  const bool periodic = GENERATE(false, true);
  const std::string extension = GENERATE(std::string(".png"), std::string(".tif"));
  CAPTURE(periodic, extension);
  TessellationOptions to;
  to.width = 2.0;
  to.height = 1.0;
  to.periodic = periodic;
  to.grains = 30;
  to.lloyd_iterations = 2;
  to.phases = two_phases();
  Rng rng(7);
  const Tessellation known = tessellate(to, rng);
  test::ScratchDir dir("image");
  const int width = 400;
  const double h = to.width / width;
  write_label_image(dir / ("cell" + extension), draw_label_image(known, width));
  const LabelImage image = read_label_image(dir / ("cell" + extension));
  REQUIRE(image.width == 400);
  REQUIRE(image.height == 200);
  ImageTessellationOptions o;
  o.pixel_size = h;
  o.tolerance = 1.0;
  o.min_grain_pixels = 8;
  o.merge_small = true;  // a sliver the drawing cut off a grain's corner goes to its neighbour
  o.periodic = periodic;
  o.phases = two_phases();
  for (const Grain& g : known.grains)
    o.label_phases.push_back({static_cast<std::uint32_t>(g.id + 1), static_cast<std::uint32_t>(g.id + 1), g.phase});
  Rng unused(1);
  const Tessellation back = image_tessellation(image, o, unused, "cell" + extension);
  REQUIRE(back.grains.size() == known.grains.size());
  CHECK(back.width == Approx(known.width).epsilon(1e-12));
  CHECK(back.height == Approx(known.height).epsilon(1e-12));
  CHECK(back.partners.axis[0].empty() == !periodic);
  // Each grain found by the label under its seed, once.
  std::vector<int> known_of(back.grains.size());
  std::set<int> found;
  for (const Grain& g : back.grains) {
    const int i = static_cast<int>(g.seed.x / h), j = static_cast<int>(g.seed.y / h);
    known_of[g.id] = static_cast<int>(image.at(i, j)) - 1;
    found.insert(known_of[g.id]);
  }
  CHECK(found.size() == known.grains.size());
  for (const Grain& g : back.grains) {
    const Grain& k = known.grains[known_of[g.id]];
    CAPTURE(g.id, k.id, g.area, k.area);
    CHECK(std::abs(g.area - k.area) <= perimeter(known, k.id) * h);
    CHECK(g.phase == k.phase);
  }
  // Neighbours: every pair sharing two pixels of boundary or more found; any other found
  // within a pixel diagonal of each other (where a thin grain between them drew thinner
  // than a pixel).
  const auto lengths = shared_lengths(known);
  std::set<std::pair<int, int>> traced;
  for (const Grain& g : back.grains)
    for (int n : g.neighbours) traced.insert(std::minmax(known_of[g.id], known_of[n]));
  for (const auto& [pair, length] : lengths)
    if (length >= 2.0 * h) CHECK(traced.count(pair) == 1);
  for (const auto& [a, b] : traced)
    if (lengths.count({a, b}) == 0) CHECK(gap(known, a, b) <= std::sqrt(2.0) * h);
  for (std::size_t p = 0; p < known.phases.size(); ++p)
    CHECK(std::abs(back.stats.phases[p].achieved_fraction - known.stats.phases[p].achieved_fraction) <= 0.005);
}

TEST_CASE("Traced at zero tolerance, each grain's area is its pixels', an island a hole of its host",
          "[tessellate][image]") {
  // clang-format off
  const LabelImage image = from_rows({{1, 1, 1, 1, 2, 2},
                                      {1, 3, 3, 1, 2, 2},
                                      {1, 3, 1, 1, 4, 2},
                                      {1, 1, 1, 4, 4, 2}});
  // clang-format on
  Rng rng(1);
  const Tessellation t = image_tessellation(image, plain_options(), rng, "hand.png");
  REQUIRE(t.grains.size() == 4);
  std::map<int, int> pixels;
  for (std::uint32_t v : image.labels) ++pixels[static_cast<int>(v)];
  std::multiset<double> areas, expected;
  for (const Grain& g : t.grains) areas.insert(g.area);
  for (const auto& [label, n] : pixels) expected.insert(n * 0.25);
  CHECK(areas == expected);
  int holes = 0;
  for (const Region& r : t.regions) holes += static_cast<int>(r.rings.size()) - 1;
  CHECK(holes == 1);
  CHECK(t.width == 3.0);
  CHECK(t.height == 2.0);
}

TEST_CASE("A grain touching itself at a pixel corner stays one simple region", "[tessellate][image]") {
  // Grain 1 is a ring closed at the corner where it meets itself diagonally.
  // clang-format off
  const LabelImage image = from_rows({{2, 2, 2, 2, 2},
                                      {2, 1, 1, 1, 2},
                                      {2, 1, 3, 1, 2},
                                      {2, 1, 1, 4, 2},
                                      {2, 2, 2, 2, 1}});
  // clang-format on
  Rng rng(1);
  ImageTessellationOptions o = plain_options();
  const Tessellation t = image_tessellation(image, o, rng, "pinch.png");  // validated inside
  CHECK(t.grains.size() == 5);  // the lone 1 at the corner is a grain of its own
  double total = 0.0;
  for (const Grain& g : t.grains) total += g.area;
  CHECK(total == Approx(25 * 0.25).epsilon(1e-12));
  for (const Grain& g : t.grains) CHECK(g.area >= 0.5 * 0.25 - 1e-12);  // a moved corner costs a quarter pixel
}

TEST_CASE("Small grains are refused naming the file, or merged into their neighbours and counted",
          "[tessellate][image]") {
  // clang-format off
  const LabelImage image = from_rows({{1, 1, 1, 2, 2, 2},
                                      {1, 5, 1, 2, 2, 2},
                                      {1, 1, 1, 2, 2, 2}});
  // clang-format on
  ImageTessellationOptions o = plain_options();
  o.min_grain_pixels = 2;
  Rng rng(1);
  REQUIRE_THROWS_AS(image_tessellation(image, o, rng, "small.png"), SmallGrainsError);
  REQUIRE_THROWS_WITH(image_tessellation(image, o, rng, "small.png"),
                      Catch::Contains("small.png: 1 grain of fewer than 2 pixels (the smallest 1 pixel of label 5 at "
                                      "pixel (1, 1)"));
  o.merge_small = true;
  const Tessellation t = image_tessellation(image, o, rng, "small.png");
  CHECK(t.grains.size() == 2);
  CHECK(t.stats.removed_grains == 1);
  for (const Grain& g : t.grains) CHECK(g.area == 9 * 0.25);
}

TEST_CASE("A label the phase table does not name is refused with its pixel count", "[tessellate][image]") {
  const LabelImage image = from_rows({{1, 1, 7, 7}, {1, 1, 7, 7}});
  ImageTessellationOptions o = plain_options();
  o.label_phases = {{1, 1, 0}};
  Rng rng(1);
  REQUIRE_THROWS_WITH(image_tessellation(image, o, rng, "a.png"),
                      "a.png: label 7 (4 pixels) has no phase in the table");
}

TEST_CASE("A file that is not a PNG or TIFF image is refused naming it", "[tessellate][image]") {
  test::ScratchDir dir("image-bad");
  std::ofstream(dir / "notes.png") << "not an image\n";
  REQUIRE_THROWS_WITH(read_label_image(dir / "notes.png"), Catch::Contains("notes.png: not a PNG or TIFF image"));
  REQUIRE_THROWS_AS(read_label_image(dir / "missing.png"), IoError);
}

TEST_CASE("Label images keep their rows: the file's top row is the cell's top", "[tessellate][image]") {
  // 3 x 2 8-bit grey images with the rows 1 2 3 (top) and 4 5 6, written byte by byte as
  // the PNG and TIFF specifications lay them out (the TIFF uncompressed, no orientation tag).
  static constexpr unsigned char kPng[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00,
      0x03, 0x00, 0x00, 0x00, 0x02, 0x08, 0x00, 0x00, 0x00, 0x00, 0xb8, 0x1f, 0x39, 0xc6, 0x00, 0x00, 0x00, 0x10, 0x49,
      0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x60, 0x64, 0x62, 0x66, 0x60, 0x61, 0x65, 0x03, 0x00, 0x00, 0x46, 0x00, 0x16,
      0x77, 0xf5, 0xc8, 0x7f, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
  };
  static constexpr unsigned char kTiff[] = {
      0x49, 0x49, 0x2a, 0x00, 0x0e, 0x00, 0x00, 0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x09, 0x00, 0x00, 0x01, 0x03,
      0x00, 0x01, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x01, 0x01, 0x03, 0x00, 0x01, 0x00, 0x00, 0x00, 0x02, 0x00,
      0x00, 0x00, 0x02, 0x01, 0x03, 0x00, 0x01, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0x03, 0x01, 0x03, 0x00, 0x01,
      0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x06, 0x01, 0x03, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00,
      0x11, 0x01, 0x04, 0x00, 0x01, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0x15, 0x01, 0x03, 0x00, 0x01, 0x00, 0x00,
      0x00, 0x01, 0x00, 0x00, 0x00, 0x16, 0x01, 0x03, 0x00, 0x01, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x17, 0x01,
      0x04, 0x00, 0x01, 0x00, 0x00, 0x00, 0x06, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  };
  test::ScratchDir dir("image-rows");
  std::ofstream(dir / "rows.png", std::ios::binary).write(reinterpret_cast<const char*>(kPng), sizeof kPng);
  std::ofstream(dir / "rows.tif", std::ios::binary).write(reinterpret_cast<const char*>(kTiff), sizeof kTiff);
  const LabelImage expected = from_rows({{1, 2, 3}, {4, 5, 6}});
  for (const char* name : {"rows.png", "rows.tif"}) {
    const LabelImage image = read_label_image(dir / name);
    CHECK(image.width == 3);
    CHECK(image.labels == expected.labels);
    CHECK(image.at(0, 0) == 4);  // bottom left
  }
  // Written and read again, 16-bit labels unchanged.
  LabelImage wide = expected;
  wide.labels[1] = 40000;
  for (const char* name : {"wide.png", "wide.tif"}) {
    write_label_image(dir / name, wide);
    CHECK(read_label_image(dir / name).labels == wide.labels);
  }
}
