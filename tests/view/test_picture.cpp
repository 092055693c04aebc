// What pictures carry besides the mesh: round ticks on colour bars and axes, a scale bar
// of a round length, the unit's name, and a row under the picture for the key.
#include <cmath>
#include <cstdint>
#include <random>

#include <catch2/catch.hpp>

#include "helpers.hpp"
#include "tessellate/tessellation.hpp"
#include "view/picture.hpp"
#include "tessellate/tessellate.hpp"

using namespace grainmesh;

namespace {

// The height in pixels a PNG's header gives (big-endian, bytes 20 to 23).
int png_height(const std::filesystem::path& file) {
  const std::string bytes = test::read_file(file);
  REQUIRE(bytes.size() > 24);
  int h = 0;
  for (int k = 20; k < 24; ++k) h = h * 256 + static_cast<unsigned char>(bytes[static_cast<std::size_t>(k)]);
  return h;
}

// Whether x is 1, 2 or 5 times a power of ten.
bool round_number(double x) {
  const double power = std::pow(10.0, std::floor(std::log10(x) + 1e-12));
  const double f = x / power;
  return std::abs(f - 1) < 1e-9 || std::abs(f - 2) < 1e-9 || std::abs(f - 5) < 1e-9;
}

}  // namespace

TEST_CASE("ticks are round, evenly spaced and inside the range, a scale bar round and at most as long as asked",
          "[export][picture]") {
  CHECK(nice_ticks(131.2, 331.7) == std::vector<double>{150, 200, 250, 300});
  CHECK(nice_ticks(-0.3, 0.3) == std::vector<double>{-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3});
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-12.0, 12.0), unit(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const double scale = std::pow(10.0, exponent(rng)), a = unit(rng) * scale, b = unit(rng) * scale;
    const double lo = std::min(a, b), hi = std::max(a, b);
    if (!(hi > lo)) continue;
    const std::vector<double> t = nice_ticks(lo, hi);
    INFO(lo << " " << hi);
    REQUIRE(t.size() >= 2);
    CHECK(t.size() <= 7);
    CHECK(t.front() >= lo - 1e-9 * (hi - lo));
    CHECK(t.back() <= hi + 1e-9 * (hi - lo));
    const double step = t[1] - t[0];
    CHECK(round_number(step));
    for (std::size_t i = 2; i < t.size(); ++i) CHECK(t[i] - t[i - 1] == Approx(step).epsilon(1e-9));
    const double bar = scale_bar_length(hi - lo);
    CHECK(round_number(bar));
    CHECK(bar <= (hi - lo) * (1 + 1e-12));
    CHECK(bar > 0.2 * (hi - lo));  // the next round number up would be too long
  }
  CHECK(scale_bar_length(0.75) == 0.5);
  CHECK(scale_bar_length(3.0) == 2.0);
  CHECK(length_unit_name(1e-6) == "\u00b5m");
  CHECK(length_unit_name(1e-3) == "mm");
  CHECK(length_unit_name(2e-6) == "x 2e-06 m");
}

TEST_CASE("a legend or a scale bar adds a row under the picture", "[export][picture]") {
  test::ScratchDir dir("picture");
  TessellationOptions o;
  o.width = 2.0;
  o.height = 1.0;
  o.grains = 30;
  o.phases = {Phase{"WC", 0.0, true, 700e9, 0.24, {}}, Phase{"Co", 0.2, false, 211e9, 0.31, {}}};
  Rng rng(2);
  const Tessellation t = tessellate(o, rng);
  write_tessellation_png(dir / "bare.png", t, {.width_px = 600});
  write_tessellation_png(dir / "key.png", t,
                         {.width_px = 600, .legend = {"WC", "Co"}, .scale_bar = true, .length_unit = "\u00b5m"});
  CHECK(png_height(dir / "key.png") == png_height(dir / "bare.png") + 30);
  CHECK(png_height(dir / "bare.png") == 600 / 2 + 20);  // 560 px for 2 x 1, the margins
}

TEST_CASE("a signed field is drawn with a diverging map about zero, a magnitude with a sequential one", "[export][picture]") {
  test::ScratchDir dir("picture-signed");
  // Two triangles of a unit square, one in tension and one in compression.
  TriMesh mesh;
  mesh.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<double> field{-3.0, 1.0};
  write_mesh_png(dir / "sequential.png", mesh, {.width_px = 200, .field = field, .field_name = "sigma_xx (MPa)"});
  write_mesh_png(dir / "signed.png", mesh,
                 {.width_px = 200, .field = field, .field_name = "sigma_xx (MPa)", .signed_field = true});
  CHECK(test::read_file(dir / "signed.png") != test::read_file(dir / "sequential.png"));
  // The range is symmetric about zero: the same picture whatever the sign of the field
  // but for the colours swapped, so a field and its negation differ, and a field of zeros
  // (no range at all) is drawn too.
  write_mesh_png(dir / "negated.png", mesh,
                 {.width_px = 200, .field = {3.0, -1.0}, .field_name = "sigma_xx (MPa)", .signed_field = true});
  CHECK(test::read_file(dir / "negated.png") != test::read_file(dir / "signed.png"));
  CHECK_NOTHROW(write_mesh_png(dir / "zero.png", mesh,
                               {.width_px = 200, .field = {0.0, 0.0}, .field_name = "tau_xy (MPa)", .signed_field = true}));
}
