// `tessellation.image`: a label image (drawn by the test from a known tessellation of ours)
// run through everything downstream as a user would — meshed conformingly, exported,
// solved on a periodic cell (checkMesh clean) — with phases from a label table; bad images
// and keys refused in one line naming them, nothing written.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

#include "helpers.hpp"
#include "tessellate/label_image.hpp"
#include "tessellate/tessellate.hpp"

using namespace grainmesh;
using test::run_grainmesh;
namespace fs = std::filesystem;

namespace {

// A config reading `image`, with `domain` lines and `more` keys of [tessellation], then
// `sections`.
void write_config(const fs::path& file, const fs::path& image, const std::string& domain, const std::string& more,
                  const std::string& sections = "") {
  std::ofstream(file) << "[domain]\n"
                      << domain << "\n[tessellation]\nimage = " << image.string() << "\n"
                      << more
                      << "\n[phase.WC]\nfraction = rest\nE = 700e9\nnu = 0.2\n[phase.Co]\nfraction = 0.3\n"
                         "E = 200e9\nnu = 0.3\n[output]\npictures = none\n[export]\nconvert_to_meters = 1e-6\n"
                      << sections;
}

// `grains` grains in a 2 x 1 cell drawn 200 x 100 pixels; grain g labelled g + 1.
LabelImage drawn(bool periodic, int grains) {
  TessellationOptions o;
  o.width = 2.0;
  o.height = 1.0;
  o.periodic = periodic;
  o.grains = grains;
  o.lloyd_iterations = 3;
  o.phases = {
      Phase{.name = "WC", .fraction = 1.0, .rest = false, .youngs_modulus = 700e9, .poisson_ratio = 0.2, .alpha = {}}};
  Rng rng(11);
  return draw_label_image(tessellate(o, rng), 200);
}

nlohmann::json report(const fs::path& dir) { return nlohmann::json::parse(test::read_file(dir / "report.json")); }

}  // namespace

TEST_CASE("a periodic label image is meshed conformingly, exported and solved like a generated cell", "[cli][image]") {
  test::ScratchDir dir("image-run");
  write_label_image(dir / "grains.png", drawn(true, 16));
  write_config(dir / "run.ini", dir / "grains.png", "periodic = true",
               "image_pixel_size = 0.01\nimage_small_grains = merge\nimage_min_grain = 6\n"
               "image_phases = 1-11: WC, 12-16: Co",
               "[mesh]\ntriangles_per_grain = 40\n");
  const auto r = run_grainmesh({"run", (dir / "run.ini").string(), "-o", (dir / "out").string(), "--solve"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const auto rep = report(dir / "out");
  CHECK(rep["grains"] == 16);
  CHECK(rep["mesh_check"]["failed_checks"] == 0);
  CHECK(rep["solved"] == true);
  const auto tess = nlohmann::json::parse(test::read_file(dir / "out" / "tessellation.json"));
  CHECK(tess["domain"]["width"].get<double>() == Approx(2.0).epsilon(1e-15));
  CHECK(tess["domain"]["height"].get<double>() == Approx(1.0).epsilon(1e-15));
  // Labels 12 to 16 are Co: five grains of it.
  int co = 0;
  for (const auto& g : tess["grains"]) co += g["phase"] == 1 ? 1 : 0;
  CHECK(co == 5);
}

TEST_CASE("bad label images and keys are refused in one line naming the file or key, nothing written", "[cli][image]") {
  test::ScratchDir dir("image-bad-cli");
  write_label_image(dir / "good.png", drawn(false, 6));
  LabelImage speck = drawn(false, 6);
  speck.labels[speck.width * 50 + 100] = 9;  // one pixel of its own
  write_label_image(dir / "speck.png", speck);
  std::ofstream(dir / "notes.png") << "grain boundaries\n";
  const auto config = [&](const std::string& name, const fs::path& image, const std::string& domain,
                          const std::string& more = "image_pixel_size = 0.01") {
    write_config(dir / name, image, domain, more);
    return (dir / name).string();
  };
  const std::vector<test::Refusal> cases{
      {{"run", config("notes.ini", dir / "notes.png", "periodic = false")}, 2, "notes.png: not a PNG or TIFF image"},
      {{"run", config("none.ini", dir / "none.png", "periodic = false")}, 2, "none.png"},
      {{"run", config("speck.ini", dir / "speck.png", "periodic = false")},
       2,
       "tessellation.image_min_grain: " + (dir / "speck.png").string() +
           ": 1 grain of fewer than 4 pixels (the smallest 1 pixel of label 9 at pixel (100, 50)"},
      {{"run",
        config("table.ini", dir / "good.png", "periodic = false", "image_pixel_size = 0.01\nimage_phases = 1-5: WC")},
       2,
       "tessellation.image_phases: " + (dir / "good.png").string() + ": label 6 ("},
      {{"run",
        config("phase.ini", dir / "good.png", "periodic = false", "image_pixel_size = 0.01\nimage_phases = 1-6: TiC")},
       2,
       "tessellation.image_phases: no phase is named 'TiC'"},
      {{"run", config("periodic.ini", dir / "good.png", "")}, 2, "domain.periodic: say whether"},
      {{"run", config("size.ini", dir / "good.png", "periodic = false", "")},
       2,
       "tessellation.image_pixel_size: missing"},
      {{"run", config("width.ini", dir / "good.png", "periodic = false\nwidth = 3")},
       2,
       "domain.width: must be the image's width, 200 x 100 pixels of 0.01, 2 x 1"},
      {{"run", config("grains.ini", dir / "good.png", "periodic = false", "image_pixel_size = 0.01\ngrains = 5")},
       2,
       "tessellation.grains: the grains come from tessellation.image"},
      {{"run", config("depth.ini", dir / "good.png", "periodic = false\ndepth = 1")},
       2,
       "tessellation.image: label images make 2D cells"},
  };
  for (const auto& c : cases) test::check_refused(c, dir / "out");
}

TEST_CASE("the label-image example tessellates to its 60 grains with the table's phases", "[cli][image]") {
  test::ScratchDir dir("image-example");
  const fs::path examples = test::source_dir() / "data" / "examples";
  const auto r = run_grainmesh({"tessellate", (examples / "grains_image.ini").string(), "--set",
                                "tessellation.image=" + (examples / "grains_image.png").string(), "-o",
                                (dir / "out").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto tess = nlohmann::json::parse(test::read_file(dir / "out" / "tessellation.json"));
  REQUIRE(tess["grains"].size() == 60);
  int co = 0;
  for (const auto& g : tess["grains"]) co += g["phase"] == 1 ? 1 : 0;
  CHECK(co == 9);  // labels 52 to 60
  CHECK(r.err.find("warning") == std::string::npos);
}
