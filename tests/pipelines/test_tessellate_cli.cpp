// `grainmesh tessellate`, driven as a user would: outputs, reports, bad input.
#include <algorithm>
#include <cstdio>
#include <fstream>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "helpers.hpp"
#include "tessellate/descriptors.hpp"
#include "tessellate/tessellation_json.hpp"
#include "view/vtu.hpp"

using namespace grainmesh;
using test::entries;
using test::run_grainmesh;
namespace fs = std::filesystem;

TEST_CASE("every grains example tessellates and meets its phase targets", "[cli][tessellate]") {
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(test::source_dir() / "data" / "examples")) {
    const std::string stem = entry.path().stem().string();
    if (entry.path().extension() != ".ini" || stem.rfind("grains_", 0) != 0) continue;
    if (stem.rfind("grains_3d", 0) == 0) continue;  // 3D: test_tessellate_3d_cli.cpp
    if (stem == "grains_image") continue;  // its grains are the image's: test_image_cli.cpp
    ++files;
    test::ScratchDir dir("tess");
    const auto r = run_grainmesh({"tessellate", entry.path().string(), "-o", (dir / "out").string()});
    INFO(stem << "\n" << r.err);
    REQUIRE(r.exit_code == 0);
    for (const char* f : {"tessellation.json", "tessellation.vtp", "tessellation.png", "report.json"})
      CHECK(fs::file_size(dir / "out" / f) > 1000);
    const auto report = nlohmann::json::parse(test::read_file(dir / "out" / "report.json"));
    CHECK(report["grains"].get<int>() >= 50);
    for (const auto& p : report["phases"]) {
      CHECK(p.contains("name"));
      CHECK(std::abs(p["achieved_fraction"].get<double>() - p["target_fraction"].get<double>()) <= 0.01);
    }
    CHECK(report["statistics"]["sharpest_corner_deg"].get<double>() >= 30.0);
    // What grainmesh mesh will read: it parses and validates.
    const auto path = (dir / "out" / "tessellation.json").string();
    const Tessellation t = tessellation_from_json<2>(test::read_file(path), path);
    CHECK(static_cast<int>(t.grains.size()) >= report["grains"].get<int>());
    CHECK(entries(dir.path()) == 1);
  }
  CHECK(files >= 2);
}

TEST_CASE("grainmesh tessellate is reproducible from its seed", "[cli][tessellate]") {
  test::ScratchDir dir("tess");
  const std::string cfg = test::example("grains_wc_co").string();
  for (const char* out : {"a", "b"})
    REQUIRE(run_grainmesh({"tessellate", cfg, "-o", (dir / out).string()}).exit_code == 0);
  for (const char* f : {"tessellation.json", "tessellation.vtp", "tessellation.png"})
    CHECK(test::read_file(dir / "a" / f) == test::read_file(dir / "b" / f));
  REQUIRE(run_grainmesh({"tessellate", cfg, "-o", (dir / "c").string(), "--set", "tessellation.seed=2"}).exit_code == 0);
  CHECK(test::read_file(dir / "a" / "tessellation.json") != test::read_file(dir / "c" / "tessellation.json"));
}

TEST_CASE("a contiguity target is met within 0.02 on five seeds and three targets, the fractions kept",
          "[cli][tessellate]") {
  test::ScratchDir dir("contiguity");
  for (const int seed : {1, 2, 3, 4, 5})
    for (const double target : {0.1, 0.3, 0.5}) {
      const fs::path out = dir / (std::to_string(seed) + "-" + std::to_string(target));
      const auto r = run_grainmesh({"tessellate", test::example("grains_wc_co").string(), "-o", out.string(), "--set",
                                    "tessellation.arrangement=", "--set", "tessellation.seed=" + std::to_string(seed),
                                    "--set", "tessellation.contiguity=" + std::to_string(target), "--set",
                                    "tessellation.contiguity_phase=Co", "--set", "output.picture_width=200"});
      INFO("seed " << seed << ", target " << target << "\n" << r.err);
      REQUIRE(r.exit_code == 0);
      const auto report = nlohmann::json::parse(test::read_file(out / "report.json"));
      CHECK(std::abs(report["statistics"]["contiguity"]["Co"].get<double>() - target) <= 0.02);
      for (const auto& p : report["phases"])
        CHECK(std::abs(p["achieved_fraction"].get<double>() - p["target_fraction"].get<double>()) <= 0.01);
      // The tessellation as written gives the same contiguity (grainmesh mesh reads it).
      const Tessellation t = tessellation_from_json<2>(test::read_file(out / "tessellation.json"), "tessellation.json");
      CHECK(t.stats.phases.empty());  // statistics are computed, not read: from the descriptors here
      CHECK(phase_descriptors(t)[1].contiguity ==
            Approx(report["statistics"]["contiguity"]["Co"].get<double>()).epsilon(1e-9));
    }
}

TEST_CASE("binder mode: a contiguity target is met within 0.02 on five seeds and three targets, the binder's fraction kept",
          "[cli][tessellate]") {
  test::ScratchDir dir("binder-contiguity");
#ifdef GRAINMESH_SANITIZED
  const std::vector<int> seeds{1};  // the point there is memory, not coverage of seeds (101 s for five)
#else
  const std::vector<int> seeds{1, 2, 3, 4, 5};
#endif
  for (const int seed : seeds)
    for (const double target : {0.2, 0.4, 0.6}) {
      const fs::path out = dir / (std::to_string(seed) + "-" + std::to_string(target));
      const auto r = run_grainmesh({"tessellate", test::example("grains_binder").string(), "-o", out.string(), "--set",
                                    "phase.Co.fraction=0.08", "--set", "tessellation.seed=" + std::to_string(seed),
                                    "--set", "tessellation.contiguity=" + std::to_string(target), "--set",
                                    "output.picture_width=200"});
      INFO("seed " << seed << ", target " << target << "\n" << r.err);
      REQUIRE(r.exit_code == 0);
      const auto report = nlohmann::json::parse(test::read_file(out / "report.json"));
      CHECK(std::abs(report["statistics"]["contiguity"]["WC"].get<double>() - target) <= 0.02);
      for (const auto& p : report["phases"])
        CHECK(std::abs(p["achieved_fraction"].get<double>() - p["target_fraction"].get<double>()) <= 0.005);
      // As written and read back: the grains touch (WC-WC edges) and the binder is one phase.
      const Tessellation t = tessellation_from_json<2>(test::read_file(out / "tessellation.json"), "tessellation.json");
      CHECK(phase_descriptors(t)[0].contiguity ==
            Approx(report["statistics"]["contiguity"]["WC"].get<double>()).epsilon(1e-9));
      if (seed == 1 && target == 0.6) {  // meshed: conforming across the contacts and the binder's pockets
        const auto m = run_grainmesh({"mesh", (out / "tessellation.json").string(), "-o", (dir / "mesh").string()});
        INFO(m.err);
        CHECK(m.exit_code == 0);
      }
    }
}

TEST_CASE("binder mode's contacts on Laguerre cells without Lloyd steps: no folded grain, no corner sharper than "
          "the cells' own",
          "[cli][tessellate]") {
  // Short faces beside long ones: a contact there once folded its grain onto itself
  // ("region 9 has a ring that is not simple") and left 3.7 degree binder corners.
  test::ScratchDir dir("binder-laguerre");
  double sharpest[2] = {0.0, 0.0};
  for (const bool target : {false, true}) {
    const fs::path out = dir / (target ? "target" : "wrapped");
    std::vector<std::string> args{"tessellate", test::example("grains_binder").string(), "-o", out.string(),
                                  "--set", "phase.Co.fraction=0.1", "--set", "tessellation.seed=3", "--set",
                                  "tessellation.lloyd_iterations=0", "--set", "tessellation.size_cv=0.5"};
    if (target) args.insert(args.end(), {"--set", "tessellation.contiguity=0.3"});
    const auto r = run_grainmesh(args);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const auto report = nlohmann::json::parse(test::read_file(out / "report.json"));
    sharpest[target] = report["statistics"]["sharpest_corner_deg"].get<double>();
    if (target) CHECK(std::abs(report["statistics"]["contiguity"]["WC"].get<double>() - 0.3) <= 0.02);
  }
  CHECK(sharpest[1] >= sharpest[0] - 1e-9);
}

TEST_CASE("bad tessellation input gives one line naming the key and no output", "[cli][tessellate]") {
  test::ScratchDir dir("tess");
  const std::string grain = test::example("grains_wc_co").string();
  const std::string binder = test::example("grains_binder").string();
  struct Case {
    std::string config;
    std::vector<std::string> sets;
    std::string says;
  };
  const std::vector<Case> cases{
      {grain, {"tessellation.grains=0"}, "tessellation.grains: must be at least 1"},
      {grain, {"tessellation.grains=-3"}, "tessellation.grains: must be at least 1"},
      {grain, {"domain.width=0"}, "domain.width: must be positive"},
      {grain, {"domain.height=-1.7"}, "domain.height: must be positive"},
      {grain, {"phase.WC.fraction=0.5"}, "the phase fractions sum to 0.65, not 1"},
      {grain, {"phase.Co.fraction=1"}, "leaving nothing for the rest phase"},
      {grain, {"phase.Co.fraction=rest"}, "phase.Co.fraction: only one phase may take the rest"},
      {grain, {"tessellation.phase_mode=layered"}, "tessellation.phase_mode: unknown mode 'layered'"},
      {grain, {"tessellation.arrangement=striped"}, "tessellation.arrangement: unknown arrangement"},
      {grain, {"tessellation.grain_size=1e-7"}, "give either tessellation.grains or tessellation.grain_size"},
      {grain, {"phase.Co.nu=0.5"}, "phase.Co.nu: must lie in (-1, 0.5)"},
      {grain, {"phase.Co.E=-1"}, "phase.Co.E: must be positive"},
      {grain, {"phase.Co.colour=red"}, "unknown key 'phase.Co.colour'"},
      {binder, {"phase.Co.fraction=0.9999999999999"}, "phase.Co.fraction"},
      {binder, {"tessellation.matrix_phase=Ni"}, "tessellation.matrix_phase: no phase is named 'Ni'"},
      {binder, {"phase.WC.fraction=0.88", "phase.Co.fraction=0.2"}, "the phase fractions sum to 1.08, not 1"},
      {grain, {"tessellation.contiguity=0.5"}, "tessellation.contiguity: give tessellation.arrangement or tessellation.contiguity, not both"},
      {grain, {"tessellation.arrangement=", "tessellation.contiguity=1.2"}, "tessellation.contiguity: must lie in (0, 1), got 1.2"},
      {grain, {"tessellation.arrangement=", "tessellation.contiguity=0.3", "tessellation.contiguity_phase=Ni"},
       "tessellation.contiguity_phase: no phase is named 'Ni'"},
      {grain, {"tessellation.contiguity_phase=Co"}, "tessellation.contiguity_phase: only used with tessellation.contiguity"},
      {binder, {"tessellation.contiguity=0.3", "tessellation.contiguity_phase=Co"},
       "tessellation.contiguity_phase: binder mode sets the contiguity of the grains, not of the matrix 'Co'"},
      // 12 % Co: with every interface but those near the cell's sides left without binder,
      // the layer left grows so thick that the contacts shrink to this.
      {binder, {"tessellation.contiguity=0.95"},
       "tessellation.contiguity: 0.95 is out of reach for phase WC with these grains and fractions (seed 7): "
       "binder-free contacts between grains move its contiguity from 0 to 0.582; ask within that"},
      // 15 % Co in grains of WC's size: WC touches itself along most of its boundary.
      {grain, {"tessellation.arrangement=", "tessellation.contiguity=0.3"},
       "tessellation.contiguity: 0.3 is out of reach for phase WC with these grains and fractions (seed 1): trading "
       "like-sized grains' labels moves its contiguity from 0.814 to 0.947; ask within that"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args{"tessellate", c.config, "-o", (dir / "out").string()};
    for (const auto& s : c.sets) {
      args.push_back("--set");
      args.push_back(s);
    }
    const auto r = run_grainmesh(args);
    INFO("set " << c.sets.front() << "\nstderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.says) != std::string::npos);
    CHECK(r.err.rfind("grainmesh: error: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(dir / "out"));
    CHECK(entries(dir.path()) == 0);
  }
}

TEST_CASE("grainmesh mesh meshes a tessellation and checks its conformity", "[cli][mesh]") {
  test::ScratchDir dir("mesh");
  REQUIRE(run_grainmesh({"tessellate", test::example("grains_wc_co").string(), "-o", (dir / "t").string(), "--set",
                         "tessellation.grains=60"})
              .exit_code == 0);
  const std::string tess = (dir / "t" / "tessellation.json").string();
  const auto r = run_grainmesh({"mesh", tess, "-o", (dir / "m").string(), "--set", "mesh.triangles_per_grain=40"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (const char* f : {"mesh.vtu", "mesh.png", "mesh_detail.png"}) CHECK(fs::file_size(dir / "m" / f) > 1000);
  const auto report = nlohmann::json::parse(test::read_file(dir / "m" / "report.json"));
  CHECK(report["dimensions"] == 2);
  CHECK(report["mesh"]["cells_per_grain_mean"].get<double>() > 20.0);
  for (const char* axis : {"x", "y"}) CHECK(report["pairs"][axis].get<int>() > 0);

  // The checker on the written mesh: it conforms; moved off its place, one node does not.
  const std::string vtu = (dir / "m" / "mesh.vtu").string();
  const auto ok = run_grainmesh({"check", tess, vtu});
  INFO(ok.err);
  CHECK(ok.exit_code == 0);
  CHECK(ok.out.find("conforms") != std::string::npos);
  // Its measured figures: grain areas as the tessellation's, every periodic node on its
  // partner's image exactly, and as many pairs as the mesh reported.
  {
    const auto at = ok.out.find("grain areas within ");
    REQUIRE(at != std::string::npos);
    double area_error = 1.0, pair_mismatch = 1.0;
    std::size_t pairs_x = 0, pairs_y = 0;
    REQUIRE(std::sscanf(ok.out.c_str() + at, "grain areas within %lf, %zu + %zu periodic node pairs within %lf",
                        &area_error, &pairs_x, &pairs_y, &pair_mismatch) == 4);
    CHECK(area_error <= 1e-9);
    CHECK(pair_mismatch == 0.0);
    CHECK(pairs_x == report["pairs"]["x"].get<std::size_t>());
    CHECK(pairs_y == report["pairs"]["y"].get<std::size_t>());
  }
  {
    VtuContents moved = read_vtu(vtu);
    TriMesh m = *as_triangles(moved.mesh);
    const auto field = std::find_if(moved.fields.begin(), moved.fields.end(), [](const auto& f) { return f.name == "grain"; });
    REQUIRE(field != moved.fields.end());
    const auto& grain = std::get<std::vector<int>>(field->values);
    std::vector<int> grain_of(m.points.size(), -1);  // a node's grain; -2 once two grains share it
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      for (int v : m.triangles[t]) grain_of[v] = grain_of[v] == -1 || grain_of[v] == grain[t] ? grain[t] : -2;
    const auto t = std::find_if(m.triangles.begin(), m.triangles.end(), [&](const auto& tr) { return grain_of[tr[0]] == -2; });
    REQUIRE(t != m.triangles.end());
    Vec2& p = m.points[(*t)[0]];
    p = p + 0.2 * (m.points[(*t)[1]] - p);  // a node of a grain boundary leaves its place
    moved.mesh = cell_mesh(m);
    write_vtu(dir / "moved.vtu", moved.mesh, moved.fields);
  }
  const auto bad = run_grainmesh({"check", tess, (dir / "moved.vtu").string()});
  CHECK(bad.exit_code == 3);
  CHECK(bad.err.find("moved.vtu: conformity: ") != std::string::npos);
  CHECK(std::count(bad.err.begin(), bad.err.end(), '\n') == 1);

  // Bad input: one line, non-zero exit, no output directory.
  std::ofstream(dir / "broken.json") << "{\"format\": \"grainmesh-tessellation\", \"version\": 1";
  {  // well-formed, but a grain's recorded area no longer matches its polygon
    auto doc = nlohmann::json::parse(test::read_file(tess));
    doc["grains"][0]["area"] = 2.0 * doc["grains"][0]["area"].get<double>();
    std::ofstream(dir / "invalid.json") << doc.dump();
  }
  const std::vector<test::Refusal> cases{
      {{"mesh", (dir / "none.json").string()}, 4, "none.json: cannot open tessellation file"},
      {{"mesh", (dir / "broken.json").string()}, 3, "broken.json: "},
      {{"mesh", tess, "--set", "mesh.size=0"}, 2, "mesh.size: must be positive"},
      {{"mesh", tess, "--set", "mesh.size=-1"}, 2, "mesh.size: must be positive"},
      {{"mesh", (dir / "invalid.json").string()}, 3, "invalid.json: "},
      {{"mesh", tess, "--set", "phase.Ni.size=0.01"}, 2, "phase.Ni.size: unknown phase 'Ni' (the tessellation's phases: WC, Co)"},
      {{"mesh", tess, "--set", "mesh.boundary_size=-1e-9"}, 2, "mesh.boundary_size: must be positive (or 0 for none)"},
      {{"mesh", tess, "--set", "mesh.gradient=0"}, 2, "mesh.gradient: must lie between 0.05 and 10"},
      {{"mesh", tess, "--set", "mesh.triangles_per_grain=1"}, 2, "mesh.triangles_per_grain: must lie between"},
  };
  for (const auto& c : cases) test::check_refused(c, dir / "out");
}
