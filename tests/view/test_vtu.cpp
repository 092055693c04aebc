#include <catch2/catch.hpp>

#include "common/errors.hpp"
#include "helpers.hpp"
#include "view/picture.hpp"
#include "view/vtu.hpp"

using namespace grainmesh;

namespace {
TriMesh square() { return {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}}; }
const std::vector<int> kLabels{0, 1};  // one per triangle of square()
}  // namespace

TEST_CASE("VTU files read back exactly", "[export]") {
  test::ScratchDir dir("vtu");
  const TriMesh m = square();
  write_vtu(dir / "m.vtu", m, {{"region", kLabels}, {"quality", std::vector<double>{0.25, 0.75}}});
  const VtuContents back = read_vtu(dir / "m.vtu");
  CHECK(back.mesh.points == m.points);
  REQUIRE(as_triangles(back.mesh).has_value());
  CHECK(as_triangles(back.mesh)->triangles == m.triangles);
  REQUIRE(back.ints("region") != nullptr);
  CHECK(*back.ints("region") == kLabels);
  CHECK(back.ints("quality") == nullptr);  // not an integer array
  CHECK(back.ints("grain") == nullptr);
  REQUIRE(back.fields.size() == 2);
  CHECK(back.fields[0].name == "region");
  CHECK(std::get<std::vector<int>>(back.fields[0].values) == kLabels);
  CHECK(back.fields[1].name == "quality");
  CHECK(std::get<std::vector<double>>(back.fields[1].values) == std::vector<double>{0.25, 0.75});
}

TEST_CASE("VTU polygonal cells read back exactly, triangles among them", "[export]") {
  test::ScratchDir dir("vtu");
  CellMesh m;
  m.points = {{0, 0}, {1, 0}, {2, 0.5}, {1, 1}, {0, 1}};
  m.add_cell(std::vector<int>{0, 1, 3, 4});
  m.add_cell(std::vector<int>{1, 2, 3});
  write_vtu(dir / "m.vtu", m, {{"grain", std::vector<int>{4, 7}}});
  const VtuContents back = read_vtu(dir / "m.vtu");
  CHECK(back.mesh.points == m.points);
  CHECK(back.mesh.start == m.start);
  CHECK(back.mesh.corners == m.corners);
  CHECK_FALSE(as_triangles(back.mesh).has_value());
  CHECK(*back.ints("grain") == std::vector<int>{4, 7});
}

TEST_CASE("VTU vectors, tensors and labels read back exactly", "[export]") {
  test::ScratchDir dir("vtu");
  const TriMesh m = square();
  const std::vector<double> vectors{1, 2, 3, 4, 5, 6}, tensors{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  write_vtu(dir / "m.vtu", m, {{"v", vectors, 3}, {"t", tensors, 6}}, {{"phase_names", {"WC", "Co"}}});
  const VtuContents back = read_vtu(dir / "m.vtu");
  REQUIRE(back.fields.size() == 2);
  CHECK(back.fields[0].components == 3);
  CHECK(std::get<std::vector<double>>(back.fields[0].values) == vectors);
  CHECK(back.fields[1].components == 6);
  CHECK(std::get<std::vector<double>>(back.fields[1].values) == tensors);
  REQUIRE(back.labels.size() == 1);
  CHECK(back.labels[0].name == "phase_names");
  CHECK(back.labels[0].labels == std::vector<std::string>{"WC", "Co"});
  CHECK_THROWS_WITH(write_vtu(dir / "m.vtu", m, {{"v", std::vector<double>{1, 2, 3}, 3}}),
                    Catch::Matchers::Contains("'v' has 3 values for 2 cells of 3 components"));
}

TEST_CASE("VTU output is byte-for-byte deterministic", "[export]") {
  test::ScratchDir dir("vtu");
  const TriMesh m = square();
  write_vtu(dir / "a.vtu", m, {{"region", kLabels}});
  write_vtu(dir / "b.vtu", m, {{"region", kLabels}});
  CHECK(test::read_file(dir / "a.vtu") == test::read_file(dir / "b.vtu"));
}

TEST_CASE("export errors are I/O errors naming the file", "[export]") {
  test::ScratchDir dir("vtu");
  const TriMesh m = square();
  CHECK_THROWS_AS(write_vtu(dir / "missing" / "m.vtu", m, {}), IoError);
  CHECK_THROWS_WITH(write_vtu(dir / "m.vtu", m, {{"region", std::vector<int>{1}}}),
                    Catch::Matchers::Contains("'region' has 1 values for 2 cells"));
  CHECK_THROWS_AS(read_vtu(dir / "nothing.vtu"), IoError);
}

TEST_CASE("mesh pictures are PNG files of the asked width", "[export]") {
  test::ScratchDir dir("png");
  write_mesh_png(dir / "m.png", square(), {.width_px = 300});
  const std::string png = test::read_file(dir / "m.png");
  REQUIRE(png.size() > 24);
  CHECK(png.substr(1, 3) == "PNG");
  // IHDR: width and height, big-endian, at bytes 16..23.
  auto be32 = [&](int at) {
    return (unsigned(static_cast<unsigned char>(png[at])) << 24) | (unsigned(static_cast<unsigned char>(png[at + 1])) << 16) |
           (unsigned(static_cast<unsigned char>(png[at + 2])) << 8) | unsigned(static_cast<unsigned char>(png[at + 3]));
  };
  CHECK(be32(16) == 300);
  CHECK(be32(20) == 300);  // square mesh, square picture
  CHECK_THROWS_AS(write_mesh_png(dir / "e.png", TriMesh{}), GeometryError);  // nothing to draw: not a file's fault
  // Labels filled and outlined: one per triangle, or refused naming what is short.
  write_mesh_png(dir / "l.png", square(), {.width_px = 300, .fill_by = kLabels});
  CHECK(test::read_file(dir / "l.png") != png);  // the second triangle is orange
  CHECK_THROWS_WITH(write_mesh_png(dir / "s.png", square(), {.width_px = 300, .fill_by = {0}}),
                    Catch::Matchers::Contains("the fill labelling has 1 values for 2 cells"));
  CHECK_THROWS_WITH(write_mesh_png(dir / "s.png", square(), {.width_px = 300, .outline_by = {0, 1, 2}}),
                    Catch::Matchers::Contains("the outline labelling has 3 values for 2 cells"));
}
