#include <catch2/catch.hpp>

#include "common/errors.hpp"
#include "pipelines/config.hpp"
#include "pipelines/domain_command.hpp"

using namespace grainmesh;
using Catch::Matchers::Contains;

TEST_CASE("INI sections become dotted keys and overrides replace values", "[config]") {
  const auto c = Config::from_text(
      "# comment\n[size]\nh0 = 0.1\nfunction = 1\nfunction = 2*x\n[domain]\nshape = circle(0,0,1)\n", "t.ini",
      {"size.h0=0.05", "size.function = 3"});
  CHECK(c.number("size.h0") == 0.05);
  CHECK(c.all("size.function") == std::vector<std::string>{"3"});
  CHECK(c.text("domain.shape") == "circle(0,0,1)");
  CHECK(c.number("missing.key", 7.0) == 7.0);
  CHECK(c.flag("missing.flag", true));
}

TEST_CASE("config errors name the file and the key", "[config]") {
  const auto c = Config::from_text("[a]\nx = abc\ny = 1\ny = 2\nb = maybe\nn = 1.5\n", "t.ini");
  CHECK_THROWS_WITH(c.number("a.x"), Contains("t.ini: a.x: 'abc' is not a number"));
  CHECK_THROWS_WITH(c.text("a.y"), Contains("t.ini: a.y: given 2 times"));
  CHECK_THROWS_WITH(c.flag("a.b", false), Contains("a.b: 'maybe' is not true or false"));
  CHECK_THROWS_WITH(c.integer("a.n", 0), Contains("a.n: '1.5' is not an integer"));
  CHECK_THROWS_WITH(c.text("a.z"), Contains("a.z: missing"));
  CHECK_THROWS_WITH(c.check_keys({"a.x", "a.y", "a.b"}), Contains("unknown key 'a.n'") && Contains("known here: a.x"));
  CHECK_THROWS_WITH(Config::from_text("[a]\nx = 1 # one\n\n  not a key value line  # no\n", "bad.ini"),
                    Contains("bad.ini: line 4: 'not a key value line' is not KEY = VALUE, a [section] or a # comment"));
  // Boost's own message for this line never finished (found by fuzzing).
  CHECK_THROWS_WITH(Config::from_text("%% with %invalid_line% 40\n", "bad.ini"),
                    Contains("bad.ini: line 1: '%% with %invalid_line% 40' is not"));
  CHECK_THROWS_WITH(Config::from_text("", "t.ini", {"novalue"}), Contains("--set novalue: expected KEY=VALUE"));
  CHECK_THROWS_AS(Config::from_file("/no/such/file.ini"), IoError);
}

TEST_CASE("domain configs are checked before any meshing", "[config]") {
  auto job_of = [](const std::string& text, std::vector<std::string> set = {}) {
    return read_domain_job(Config::from_text(text, "d.ini", set));
  };
  const std::string ok = "[domain]\nshape = circle(0, 0, 1)\n[size]\nh0 = 0.1\n";
  const DomainJob job = job_of(ok);
  CHECK(job.problem.h0 == 0.1);
  CHECK(job.problem.bbox.lo == Vec2{-1, -1});  // from the shape when not given
  CHECK(job.problem.curvature_angle > 0.0);
  CHECK(job_of(ok, {"size.curvature_segments=0"}).problem.curvature_angle == 0.0);
  // A key given with --set is blamed on --set, not on the file.
  CHECK_THROWS_WITH(job_of(ok, {"size.h0=0"}), Contains("--set: size.h0: must be positive"));
  CHECK_THROWS_WITH(job_of(ok + "h0 = 0\n"), Contains("d.ini: size.h0: given 2 times"));
  CHECK_THROWS_WITH(job_of(ok, {"size.h0=-1"}), Contains("size.h0"));
  CHECK_THROWS_WITH(job_of(ok, {"size.hh=1"}), Contains("unknown key 'size.hh'"));
  CHECK_THROWS_WITH(job_of("[size]\nh0 = 1\n"), Contains("domain.shape: missing"));
  CHECK_THROWS_WITH(job_of(ok, {"domain.bbox=1 1 0 0"}), Contains("domain.bbox"));
  CHECK_THROWS_WITH(job_of(ok, {"size.function=0"}), Contains("size.function"));
  CHECK_THROWS_WITH(job_of(ok, {"distmesh.max_iterations=0"}), Contains("distmesh.max_iterations"));
  // Polygon corners on the boundary become fixed points; interior ones do not.
  const DomainJob plate = job_of("[domain]\nshape = difference(polygon(-1 -1, 1 -1, 1 1, -1 1), circle(0,0,0.5))\n[size]\nh0 = 0.1\n");
  CHECK(plate.problem.fixed.size() == 4);
  CHECK(job_of("[domain]\nshape = rectangle(0, 0, 1, 1)\n[size]\nh0 = 0.1\n[fixed]\npolygon_vertices = false\n")
            .problem.fixed.empty());
}
