// The report schema: every report the tests write is checked against
// docs/report.schema.json after them all (tests/CMakeLists.txt, reports_match_schema).
// Here: that the reports do get collected, that the check fails a report that breaks the
// schema, and that schema-1 reports are read as schema 2.
#include <nlohmann/json.hpp>

#include "helpers.hpp"
#include "pipelines/report_read.hpp"

using namespace grainmesh;
using namespace grainmesh::test;
namespace fs = std::filesystem;

namespace {

// validate_reports.py over `dir`.
CommandResult validate(const fs::path& dir) {
  ScratchDir io("validate");
  const std::string cmd = "python3 " + shell_quote((source_dir() / "tests/pipelines/validate_reports.py").string()) +
                          " " + shell_quote((source_dir() / "docs/report.schema.json").string()) + " " +
                          shell_quote(dir.string()) + " > " + shell_quote((io / "out").string()) + " 2>&1";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(io / "out"), {}};
}

}  // namespace

TEST_CASE("a test's reports are collected for the schema check when its scratch directory goes", "[report]") {
  std::string written;
  std::vector<fs::path> before;
  if (fs::exists(collected_reports_dir()))
    for (const auto& e : fs::directory_iterator(collected_reports_dir())) before.push_back(e.path());
  {
    ScratchDir dir("collected");
    const auto r = run_grainmesh({"tessellate", (source_dir() / "data/default.ini").string(), "-o", (dir / "t").string()});
    REQUIRE(r.exit_code == 0);
    written = read_file(dir / "t" / "report.json");
  }
  int copies = 0;
  for (const auto& e : fs::directory_iterator(collected_reports_dir()))
    if (std::find(before.begin(), before.end(), e.path()) == before.end() &&
        e.path().filename().string().rfind("collected-", 0) == 0 && read_file(e.path()) == written)
      ++copies;
  CHECK(copies == 1);
}

TEST_CASE("the schema check passes a report as written and fails one that breaks the schema, naming the field",
          "[report]") {
  ScratchDir dir("schema");
  REQUIRE(run_grainmesh({"tessellate", (source_dir() / "data/default.ini").string(), "-o", (dir / "t").string()})
              .exit_code == 0);
  const nlohmann::ordered_json report = nlohmann::ordered_json::parse(read_file(dir / "t" / "report.json"));
  // Named other than report.json, so they are not collected themselves.
  fs::create_directories(dir / "good");
  std::ofstream(dir / "good" / "tessellate.json") << report.dump();
  CHECK(validate(dir / "good").exit_code == 0);

  const auto broken = [&](const std::string& name, nlohmann::ordered_json r, const std::string& says) {
    fs::create_directories(dir / name);
    std::ofstream(dir / name / "tessellate.json") << r.dump();
    const CommandResult v = validate(dir / name);
    INFO(v.out);
    CHECK(v.exit_code == 1);
    CHECK(v.out.find(says) != std::string::npos);
  };
  nlohmann::ordered_json r = report;
  r["phases"][0].erase("achieved_fraction");
  broken("no-fraction", r, "phases/0: 'achieved_fraction' is a required property");
  r = report;
  r.erase("schema");
  broken("no-schema", r, "'schema' is a required property");
  r = report;
  r["schema"] = 1;
  broken("old-schema", r, "schema: 2 was expected");
  r = report;
  r["statistics"]["contiguity"] = "high";
  broken("wrong-type", r, "statistics/contiguity");
}

TEST_CASE("schema-1 reports are read as schema 2: the same numbers under its names, and they validate", "[report]") {
  const fs::path data = source_dir() / "tests/pipelines/data";
  const Json old2 = Json::parse(read_file(data / "report-schema1-2d-periodic.json"));
  const Json two = read_report(data / "report-schema1-2d-periodic.json");
  CHECK(two["schema"] == 2);
  CHECK(two["dimensions"] == 2);
  const auto& c = old2["effective"]["stiffness"];
  CHECK(two["effective"]["stiffness"]["C12"].get<double>() ==
        Approx(0.5 * (c["C12"].get<double>() + c["C21"].get<double>())).epsilon(1e-15));
  CHECK(two["effective"]["stiffness"]["C16"].get<double>() ==
        Approx(0.5 * (c["C16"].get<double>() + c["C61"].get<double>())).epsilon(1e-15));
  CHECK_FALSE(two["effective"]["stiffness"].contains("C21"));
  CHECK(two["effective"]["thermal_expansion"]["xx"] == old2["effective"]["thermal_expansion"]["a11"]);
  CHECK(two["effective"]["anisotropy"]["universal"].get<double>() >= 0.0);
  CHECK(two["effective"]["anisotropy"]["universal"].get<double>() < 1e-3);  // a nearly isotropic cell
  CHECK(two["effective"]["thermal"]["levin"]["xy"] == old2["effective"]["thermal"]["levin"]["a12"]);
  CHECK(two["stresses"]["xx"]["matrix"]["volume_fraction"] == old2["stresses"]["xx"]["matrix"]["area_fraction"]);
  CHECK(two["stresses"]["xx"]["matrix"]["mean"]["zz"] == old2["stresses"]["xx"]["matrix"]["mean"]["zz"]);
  CHECK(two["stresses"]["xx"]["matrix"]["mean"]["yz"] == 0.0);

  const Json old3 = Json::parse(read_file(data / "report-schema1-3d-periodic.json"));
  const Json three = read_report(data / "report-schema1-3d-periodic.json");
  CHECK(three["dimensions"] == 3);
  CHECK(three["phases"] == old3["statistics"]["phases"]);
  CHECK_FALSE(three["statistics"].contains("phases"));
  REQUIRE(three["effective"]["load_cases"].is_array());
  CHECK(three["effective"]["load_cases"][0]["name"] == "xx");
  CHECK(three["effective"]["load_cases"][0]["corrections"] == old3["effective"]["load_cases"]["xx"]["corrections"]);
  CHECK(three["effective"]["anisotropy"]["universal"] == old3["effective"]["engineering"]["universal_anisotropy"]);

  // Upgraded, the reports keep schema 2's names and shapes where schema 1 had them: the
  // fields schema 2 added (each load case's strain and stress, a 3D phase's largest
  // principal stress) are what they lack.
  ScratchDir dir("upgraded");
  for (const auto& [name, r] : {std::pair{"two", two}, std::pair{"three", three}}) {
    Json upgraded = r;
    for (Json& lc : upgraded["effective"]["load_cases"])
      if (!lc.contains("strain")) lc["strain"] = lc["stress"] = {{"xx", 0}, {"yy", 0}, {"zz", 0}, {"yz", 0}, {"xz", 0}, {"xy", 0}};
    for (auto& [state, phases] : upgraded["stresses"].items())
      for (auto& [phase, s] : phases.items())
        if (!s.contains("max_principal")) s["max_principal"] = s["von_mises"];
    fs::create_directories(dir / name);
    std::ofstream(dir / name / "run.json") << upgraded.dump();
  }
  const CommandResult v = validate(dir.path() / "two"), w = validate(dir.path() / "three");
  INFO(v.out << w.out);
  CHECK(v.exit_code == 0);
  CHECK(w.exit_code == 0);
}

TEST_CASE("a report of a schema this grainmesh does not know is refused, naming the version", "[report]") {
  ScratchDir dir("future");
  std::ofstream(dir / "future.json") << R"({"command": "run", "schema": 3})";
  try {
    read_report(dir / "future.json");
    FAIL("read");
  } catch (const std::exception& e) {
    CHECK(std::string(e.what()).find("report schema 3") != std::string::npos);
  }
}
