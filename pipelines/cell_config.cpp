#include "pipelines/cell_config.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include "common/format.hpp"
#include "domain/shape_parser.hpp"
#include "pipelines/config_values.hpp"
#include "pipelines/material_units.hpp"

namespace grainmesh {

DiagramSettings read_diagram_settings(const Config& c, double min_edge) {
  DiagramSettings d;
  const long long lloyd = c.integer("tessellation.lloyd_iterations", 0);
  if (lloyd < 0 || lloyd > 10000) c.fail("tessellation.lloyd_iterations", "must be between 0 and 10000");
  d.lloyd_iterations = static_cast<int>(lloyd);
  d.size_cv = c.number("tessellation.size_cv", 0.0);
  if (!(d.size_cv >= 0.0 && d.size_cv <= 5.0)) c.fail("tessellation.size_cv", "must lie in [0, 5]");
  d.min_edge = c.number("tessellation.min_edge", min_edge);
  if (!(d.min_edge >= 0.0 && d.min_edge < 1.0)) c.fail("tessellation.min_edge", "must lie in [0, 1)");
  const std::string arr = c.optional_text("tessellation.arrangement").value_or("random");
  if (arr == "random") d.arrangement = Arrangement::random;
  else if (arr == "dispersed") d.arrangement = Arrangement::dispersed;
  else if (arr == "clustered") d.arrangement = Arrangement::clustered;
  else c.fail("tessellation.arrangement", "unknown arrangement '" + arr + "' (random, dispersed or clustered)");
  return d;
}

namespace {

// The seeds of tessellation.seeds, each checked inside the box.
std::vector<Vec3> read_seeds(const Config& c, Vec3 box, int dimensions) {
  const std::string what = c.source() + ": tessellation.seeds";
  std::vector<Vec3> seeds;
  for (const auto& text : c.all("tessellation.seeds")) {
    if (dimensions == 2) {
      for (const Vec2 p : parse_point_list(text, what)) seeds.push_back({p.x, p.y, 0.0});
      continue;
    }
    for (std::string_view rest = text; !rest.empty();) {
      const std::size_t comma = rest.find(',');
      const std::vector<double> v = parse_numbers(rest.substr(0, comma), 3, what + " (x y z, x y z, ...)");
      seeds.push_back({v[0], v[1], v[2]});
      rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
    }
  }
  const char* name = dimensions == 3 ? "box" : "cell";
  for (const Vec3& p : seeds) {
    bool inside = true;
    std::string at, extent;
    for (int a = 0; a < dimensions; ++a) {
      inside = inside && p[a] >= 0.0 && p[a] <= box[a];
      at += (a ? ", " : "") + to_text(p[a]);
      extent += std::string(a ? " x " : "") + "[0, " + to_text(box[a]) + "]";
    }
    if (!inside) c.fail("tessellation.seeds", "seed (" + at + ") lies outside the " + name + " " + extent);
  }
  if (seeds.empty()) c.fail("tessellation.seeds", dimensions == 3 ? "no seed given (x y z, x y z, ...)" : "no seed given (x y, x y, ...)");
  return seeds;
}

}  // namespace

GrainCount read_grain_count(const Config& c, Vec3 box, int dimensions) {
  const double most = dimensions == 3 ? 1e6 : 1e7;
  const std::string most_text = dimensions == 3 ? "a million" : "10 million";
  const char* name = dimensions == 3 ? "box" : "cell";
  if (c.has("tessellation.grains") && c.has("tessellation.grain_size"))
    c.fail("tessellation.grain_size", "give either tessellation.grains or tessellation.grain_size, not both");
  GrainCount count;
  if (c.has("tessellation.seeds")) {
    if (c.has("tessellation.grain_size"))
      c.fail("tessellation.grain_size", "give tessellation.seeds or tessellation.grain_size, not both");
    count.seeds = read_seeds(c, box, dimensions);
    if (static_cast<double>(count.seeds.size()) > most) c.fail("tessellation.seeds", "more than " + most_text + " seeds");
    count.grains = static_cast<int>(count.seeds.size());
    if (c.has("tessellation.grains") && c.integer("tessellation.grains", 0) != count.grains)
      c.fail("tessellation.grains", "is " + c.text("tessellation.grains") + " but tessellation.seeds gives " +
                                        std::to_string(count.grains) + " seeds: set it to that or leave it out");
  } else if (c.has("tessellation.grain_size")) {
    const double d = positive(c, "tessellation.grain_size");  // mean equivalent-circle (-sphere) diameter
    const double n = dimensions == 3 ? std::round(box.x * box.y * box.z / (std::numbers::pi / 6.0 * d * d * d))
                                     : std::round(box.x * box.y / (0.25 * std::numbers::pi * d * d));
    if (n < 1.0) c.fail("tessellation.grain_size", std::string("is larger than the ") + name + ": no grain fits");
    if (n > most) c.fail("tessellation.grain_size", "gives " + to_text(n) + " grains, more than " + most_text);
    count.grains = static_cast<int>(n);
  } else {
    const long long n = c.integer("tessellation.grains", 100);
    if (n < 1) c.fail("tessellation.grains", "must be at least 1, got " + c.text("tessellation.grains"));
    if (static_cast<double>(n) > most)
      c.fail("tessellation.grains", "must be at most " + most_text + (dimensions == 3 ? " in 3D" : ""));
    count.grains = static_cast<int>(n);
  }
  return count;
}

std::vector<Phase> read_phases(const Config& c) {
  const std::vector<std::string> names = c.names_in("phase");
  if (names.empty()) c.fail("phase.*.fraction", "no phase given: add a section [phase.NAME] with fraction, E and nu");
  // A section without a fraction is most often a misspelt phase ([phase.Matrix]).
  std::string defined;
  for (const auto& name : names)
    if (c.has("phase." + name + ".fraction")) defined += (defined.empty() ? "" : ", ") + name;
  std::vector<Phase> phases;
  double sum = 0.0;
  int rests = 0;
  for (const auto& name : names) {
    const std::string key = "phase." + name + ".";
    Phase p;
    p.name = name;
    if (!c.has(key + "fraction")) {
      std::string given;  // the key that brought the name in
      for (const auto& [k, v] : c.entries())
        if (given.empty() && k.rfind(key, 0) == 0) given = k;
      c.fail(given, "unknown phase '" + name + "' (" + (defined.empty() ? "no phase has a fraction" : "phases: " + defined) +
                        "); a new phase needs " + key + "fraction, " + key + "E and " + key + "nu");
    }
    if (c.text(key + "fraction") == "rest") {
      p.rest = true;
      ++rests;
      if (rests > 1) c.fail(key + "fraction", "only one phase may take the rest");
    } else {
      p.fraction = c.number(key + "fraction");
      if (!(p.fraction > 0.0 && p.fraction <= 1.0)) c.fail(key + "fraction", "must lie in (0, 1] or be rest, got " + c.text(key + "fraction"));
      sum += p.fraction;
    }
    p.youngs_modulus = positive(c, key + "E");
    check_modulus_unit(c, key + "E", p.youngs_modulus);
    if (!c.has(key + "nu")) c.fail(key + "nu", "missing (required)");
    p.poisson_ratio = c.number(key + "nu");
    if (!(p.poisson_ratio > -1.0 && p.poisson_ratio < 0.5)) c.fail(key + "nu", "must lie in (-1, 0.5), got " + c.text(key + "nu"));
    if (c.has(key + "alpha")) {
      p.alpha = c.number(key + "alpha");
      if (!std::isfinite(*p.alpha)) c.fail(key + "alpha", "must be a finite number (1/K), got " + c.text(key + "alpha"));
      check_expansion_unit(c, key + "alpha", *p.alpha);
    }
    phases.push_back(p);
  }
  const std::string last = "phase." + names.back() + ".fraction";
  if (rests == 0 && std::abs(sum - 1.0) > 1e-9)
    c.fail(last, "the phase fractions sum to " + to_text(sum) + ", not 1 (or let one phase take the rest)");
  if (rests == 1 && sum >= 1.0 - 1e-12)
    c.fail(last, "the phase fractions sum to " + to_text(sum) + ", leaving nothing for the rest phase");
  return phases;
}

// The keys that would draw the grains, refused when they come from a file.
void refuse_drawing_keys(const Config& c, const std::string& from) {
  for (const char* key : {"tessellation.grains", "tessellation.grain_size", "tessellation.seeds",
                          "tessellation.lloyd_iterations", "tessellation.size_cv", "tessellation.min_edge",
                          "tessellation.phase_mode", "tessellation.contiguity"})
    if (c.has(key)) c.fail(key, "the grains come from " + from + ": remove it");
}

}  // namespace grainmesh
