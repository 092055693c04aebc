#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/predicates.hpp"
#include "domain/polygon.hpp"
#include "fuzz/fuzz_targets.hpp"
#include "grains/conformity.hpp"
#include "grains/grain_mesh.hpp"
#include "pipelines/config.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/domain_command.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/mesh_job.hpp"
#include "pipelines/tessellate_job.hpp"
#include "tessellate/tessellation_json.hpp"
#include "tessellate/tessellate.hpp"
#include "tessellate/validate.hpp"

namespace grainmesh::fuzz {

namespace {

std::string as_text(std::span<const std::uint8_t> data) { return {data.begin(), data.end()}; }

void expect(bool ok, const std::string& what) {
  if (!ok) throw FuzzFailure(what);
}

// The tessellation every fuzzed mesh config is read against: four grains, two phases.
const Tessellation& small_tessellation() {
  static const Tessellation t = [] {
    TessellationOptions o;
    o.grains = 4;
    o.phases = {Phase{.name = "a", .fraction = 0.5, .rest = false, .youngs_modulus = 1, .poisson_ratio = 0.3, .alpha = {}},
                Phase{.name = "b", .fraction = 0, .rest = true, .youngs_modulus = 2, .poisson_ratio = 0.3, .alpha = {}}};
    Rng rng(1);
    return tessellate(o, rng);
  }();
  return t;
}

// Runs `read`; the tool's own errors are a fine answer to bad input.
template <class F>
void refused_or_read(F&& read) {
  try {
    read();
  } catch (const ConfigError&) {
  } catch (const GeometryError&) {
  } catch (const IoError&) {
  }
}

}  // namespace

void config(std::span<const std::uint8_t> data) {
  std::string text = as_text(data);
  std::vector<std::string> overrides;
  if (const auto at = text.find("\n--set\n"); at != std::string::npos) {
    std::string rest = text.substr(at + 7);
    text.resize(at);
    for (std::size_t start = 0; start <= rest.size();) {
      const auto end = std::min(rest.find('\n', start), rest.size());
      overrides.push_back(rest.substr(start, end - start));
      start = end + 1;
    }
  }
  refused_or_read([&] {
    const Config c = Config::from_text(text, "fuzz.ini", overrides);
    refused_or_read([&] { read_tessellate_job<2>(c.subset(tessellate_config_keys())); });
    refused_or_read([&] { read_mesh_job(c.subset(mesh_config_keys()), small_tessellation()); });
    refused_or_read([&] { read_foam_options(c.subset(export_config_keys())); });
    refused_or_read([&] {
      const DomainJob job = read_domain_job(c.subset(domain_config_keys()));
      const Box b = job.problem.bbox;
      for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j) {
          const Vec2 p{b.lo.x + i * b.width() / 4, b.lo.y + j * b.height() / 4};
          (void)job.problem.domain(p);
          (void)job.problem.size(p);
        }
    });
  });
}

void tessellation_json(std::span<const std::uint8_t> data) {
  Tessellation t;
  try {
    t = tessellation_from_json<2>(as_text(data), "fuzz.json");
  } catch (const GeometryError&) {
    return;
  }
  // The reader validated it; validate again to be sure it says so of what it returns.
  validate(t);
  double area = 0.0;
  for (const Region& r : t.regions) area += region_area(t, r);
  expect(std::isfinite(area) && area > 0, "accepted a tessellation without area");
  if (t.regions.size() > 24 || t.vertices.size() > 400) return;
  GrainMeshOptions o;
  o.size = std::sqrt(area / (20.0 * static_cast<double>(t.regions.size())));
  o.threads = 1;
  o.distmesh.max_iterations = 200;
  GrainMesh m;
  try {
    m = mesh_tessellation(t, o);
  } catch (const GeometryError&) {
    return;  // refused with a message: allowed
  } catch (const ConfigError&) {
    return;
  }
  check_conformity(t, m, 1e-6);  // throws GeometryError: a mesh that lies is a bug
}

namespace {

// Even-odd crossing number with exact orientation tests; p must not lie on an edge.
bool inside_by_crossings(const PolygonRings& rings, Vec2 p) {
  bool inside = false;
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      if ((a.y > p.y) == (b.y > p.y)) continue;
      if (a.y > b.y) std::swap(a, b);
      if (orient2d(a, b, p) > 0) inside = !inside;
    }
  return inside;
}

// Exactly on an edge (orientation zero, within the edge's box).
bool on_an_edge(const PolygonRings& rings, Vec2 p) {
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      if (p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) && p.y >= std::min(a.y, b.y) &&
          p.y <= std::max(a.y, b.y) && orient2d(a, b, p) == 0)
        return true;
    }
  return false;
}

std::string exact(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

double brute_distance(const PolygonRings& rings, Vec2 p) {
  double d2 = std::numeric_limits<double>::infinity();
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i)
      d2 = std::min(d2, segment_distance2(p, ring[i], ring[(i + 1) % ring.size()]));
  return std::sqrt(d2);
}

// Reads bytes in order; zero once they run out.
struct Reader {
  std::span<const std::uint8_t> data;
  std::size_t at = 0;
  bool done() const { return at >= data.size(); }
  int byte() { return done() ? 0 : data[at++]; }
  int signed_byte() { return static_cast<std::int8_t>(byte()); }
};

}  // namespace

void polygon_distance(std::span<const std::uint8_t> data) {
  Reader in{data};
  const int mode = in.byte();
  // Coordinates from 1e-8 to 1e7: the same shapes tiny and huge.
  const double scale = std::pow(10.0, (in.byte() % 16) - 8);
  PolygonRings rings;
  if (mode % 2 == 0) {
    // Raw rings on a coarse lattice: collinear, coincident and crossing vertices galore.
    while (!in.done() && rings.size() < 4) {
      const int n = in.byte() % 40;
      std::vector<Vec2> ring;
      for (int k = 0; k < n && !in.done(); ++k) ring.push_back(scale * Vec2{1.0 * in.signed_byte(), 1.0 * in.signed_byte()});
      rings.push_back(std::move(ring));
    }
  } else {
    // Star-shaped rings about the origin, simple by construction: an outer ring of up to
    // 255 vertices (enough for the edge grid) and holes inside its smallest radius.
    double inner = 1.0;
    while (!in.done() && rings.size() < 3) {
      const int n = 3 + in.byte();
      std::vector<Vec2> ring;
      double least = std::numeric_limits<double>::infinity();
      for (int k = 0; k < n; ++k) {
        const double angle = 2 * std::numbers::pi * (k + 0.45 * (in.byte() / 255.0)) / n;
        const double r = inner * (1 + in.byte()) / 256.0;
        least = std::min(least, r);
        ring.push_back(scale * 100.0 * Vec2{r * std::cos(angle), r * std::sin(angle)});
      }
      rings.push_back(std::move(ring));
      inner = 0.9 * least;
    }
  }
  try {
    validate_polygon(rings);
  } catch (const GeometryError&) {
    return;
  }
  const PolygonDistance d(rings);
  Box box;
  for (const auto& ring : rings)
    for (Vec2 v : ring) box.extend(v);
  const double extent = std::max(box.width(), box.height());
  const double tolerance = 1e-12 * extent;
  auto check = [&](Vec2 p) {
    const double got = d(p), want = brute_distance(rings, p);
    // The message only on failure: formatting it for every point was most of the time.
    const auto fail_unless = [&](bool ok, const char* what) {
      if (!ok)
        throw FuzzFailure(std::string(what) + " at (" + exact(p.x) + ", " + exact(p.y) + "): d " + exact(got) +
                          ", brute force " + exact(want));
    };
    fail_unless(std::isfinite(got), "distance not finite");
    fail_unless(std::abs(std::abs(got) - want) <= tolerance, "distance differs from the brute-force distance");
    if (on_an_edge(rings, p)) {
      fail_unless(!d.contains(p), "a point on an edge counted as strictly inside");
      return;
    }
    const bool inside = inside_by_crossings(rings, p);
    fail_unless(d.contains(p) == inside, "contains() disagrees with the crossing number");
    if (got != 0.0) fail_unless((got < 0) == inside, "distance sign disagrees with the crossing number");
    if (inside) fail_unless(d.bounds().contains(p), "a point inside lies outside bounds()");
  };
  // Every edge's ends, middle and both sides of it, up to 32 edges a ring (evenly spread):
  // each check is a brute-force pass, and more inputs find more than more points.
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); i += std::max<std::size_t>(1, ring.size() / 32)) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      const Vec2 mid = 0.5 * (a + b), off = 1e-9 * extent / norm(b - a) * perp(b - a);
      for (Vec2 p : {a, mid, mid + off, mid - off}) check(p);
    }
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j)
      check({box.lo.x + (i - 1) * box.width() / 6, box.lo.y + (j - 1) * box.height() / 6});
}

}  // namespace grainmesh::fuzz
