#include "tessellate/tessellation_json.hpp"

#include <climits>
#include <cmath>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "common/json_error.hpp"

namespace grainmesh {

namespace {

using Json = nlohmann::ordered_json;

Json point(Vec2 p) { return Json::array({p.x, p.y}); }

Json statistics(const TessellationStats& s, const std::vector<Phase>& phases) {
  Json j;
  j["grains"] = s.grains;
  j["removed_grains"] = s.removed_grains;
  j["area_mean"] = s.area_mean;
  j["area_std"] = s.area_std;
  j["diameter_mean"] = s.diameter_mean;
  j["diameter_std"] = s.diameter_std;
  j["neighbours_mean"] = s.neighbours_mean;
  j["edges_per_grain_mean"] = s.edges_per_grain_mean;
  j["edge_threshold"] = s.edge_threshold;
  j["shortest_edge"] = s.shortest_edge;
  j["shortest_torus_edge"] = s.shortest_torus_edge;
  j["sharpest_corner_deg"] = s.sharpest_corner_deg;
  j["collapsed_edges"] = s.collapsed_edges;
  j["side_jogs"] = s.side_jogs;
  j["pushed_vertices"] = s.pushed_vertices;
  j["binder_offset"] = s.binder_offset;
  j["window_origin"] = point(s.window_origin);
  Json ph = Json::array();
  for (std::size_t p = 0; p < s.phases.size(); ++p)
    ph.push_back({{"name", phases[p].name},
                  {"target_fraction", s.phases[p].target_fraction},
                  {"achieved_fraction", s.phases[p].achieved_fraction},
                  {"grains", s.phases[p].grains}});
  j["phases"] = ph;
  return j;
}

Vec2 read_point(const Json& j) { return {j.at(0).get<double>(), j.at(1).get<double>()}; }

// nlohmann turns any number into an int with a plain cast, undefined for 1e80 and silently
// wrapping 2^32 to 0 (found by fuzzing), so every index and count is read through here.
int read_int(const Json& j) {
  if (!j.is_number_integer())
    throw GeometryError("expected an integer, found " + j.dump());
  if (j.is_number_unsigned() ? j.get<std::uint64_t>() > std::uint64_t{INT_MAX}
                             : j.get<std::int64_t>() < INT_MIN || j.get<std::int64_t>() > INT_MAX)
    throw GeometryError("integer " + j.dump() + " is out of range");
  return static_cast<int>(j.get<std::int64_t>());
}

std::vector<int> read_ints(const Json& j) {
  if (!j.is_array()) throw GeometryError("expected an array of integers, found " + j.dump());
  std::vector<int> values;
  for (const Json& v : j) values.push_back(read_int(v));
  return values;
}

std::vector<std::pair<int, int>> read_pairs(const Json& j) {
  if (!j.is_array()) throw GeometryError("expected an array of pairs, found " + j.dump());
  std::vector<std::pair<int, int>> pairs;
  for (const Json& p : j) {
    const std::vector<int> v = read_ints(p);
    if (v.size() != 2) throw GeometryError("expected a pair, found " + p.dump());
    pairs.emplace_back(v[0], v[1]);
  }
  return pairs;
}

}  // namespace

std::string tessellation_to_json(const Tessellation& t) {
  Json j;
  j["format"] = "grainmesh-tessellation";
  j["version"] = 1;
  j["domain"] = {{"width", t.width}, {"height", t.height}, {"periodic", t.periodic}};
  Json phases = Json::array();
  for (const Phase& p : t.phases) {
    phases.push_back({{"name", p.name}, {"target_fraction", p.fraction}, {"rest", p.rest},
                      {"E", p.youngs_modulus}, {"nu", p.poisson_ratio}});
    if (p.alpha) phases.back()["alpha"] = *p.alpha;
  }
  j["phases"] = phases;
  Json grains = Json::array();
  for (const Grain& g : t.grains)
    grains.push_back({{"id", g.id}, {"phase", g.phase}, {"seed", point(g.seed)}, {"area", g.area},
                      {"neighbours", g.neighbours}, {"matrix", g.matrix}});
  j["grains"] = grains;
  Json vertices = Json::array();
  for (Vec2 v : t.vertices) vertices.push_back(point(v));
  j["vertices"] = vertices;
  Json edges = Json::array();
  for (const TessEdge& e : t.edges) edges.push_back({e.v0, e.v1, e.left, e.right});
  j["edges"] = edges;
  Json regions = Json::array();
  for (const Region& r : t.regions) regions.push_back({{"grain", r.grain}, {"phase", r.phase}, {"rings", r.rings}});
  j["regions"] = regions;
  j["partners"] = {{"x", t.partners.x}, {"y", t.partners.y}};
  j["statistics"] = statistics(t.stats, t.phases);
  j["statistics"].update(descriptors_json(t));
  return j.dump(1) + "\n";
}

Json descriptors_json(const Tessellation& t) {
  auto value = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  Json out;
  for (const char* key : {"contiguity", "intercept_length", "mean_free_path"}) out[key] = Json::object();
  for (std::size_t p = 0; p < t.phases.size() && p < t.stats.phases.size(); ++p) {
    const PhaseStats& s = t.stats.phases[p];
    out["contiguity"][t.phases[p].name] = value(s.contiguity);
    out["intercept_length"][t.phases[p].name] = value(s.intercept_length);
    out["mean_free_path"][t.phases[p].name] = value(s.mean_free_path);
  }
  return out;
}

Tessellation tessellation_from_json(const std::string& text, const std::string& source) {
  Tessellation t;
  try {
    const Json j = Json::parse(text);
    if (j.value("format", "") != "grainmesh-tessellation")
      throw GeometryError("not a grainmesh tessellation (format key)");
    if (read_int(j.at("version")) != 1)
      throw GeometryError("tessellation version " + j.at("version").dump() + " is not supported");
    const Json& d = j.at("domain");
    t.width = d.at("width").get<double>();
    t.height = d.at("height").get<double>();
    t.periodic = d.at("periodic").get<bool>();
    for (const Json& p : j.at("phases")) {
      t.phases.push_back(Phase{p.at("name").get<std::string>(), p.at("target_fraction").get<double>(),
                               p.at("rest").get<bool>(), p.at("E").get<double>(), p.at("nu").get<double>(), {}});
      if (p.contains("alpha")) t.phases.back().alpha = p.at("alpha").get<double>();
    }
    for (const Json& g : j.at("grains"))
      t.grains.push_back(Grain{read_int(g.at("id")), read_int(g.at("phase")), read_point(g.at("seed")),
                               g.at("area").get<double>(), read_ints(g.at("neighbours")),
                               g.at("matrix").get<bool>()});
    for (const Json& v : j.at("vertices")) t.vertices.push_back(read_point(v));
    for (const Json& e : j.at("edges")) {
      const std::vector<int> v = read_ints(e);
      if (v.size() != 4) throw GeometryError("an edge is not [v0, v1, left, right]: " + e.dump());
      t.edges.push_back({v[0], v[1], v[2], v[3]});
    }
    for (const Json& r : j.at("regions")) {
      Region region{read_int(r.at("grain")), read_int(r.at("phase")), {}};
      if (!r.at("rings").is_array()) throw GeometryError("a region's rings are not an array: " + r.at("rings").dump());
      for (const Json& ring : r.at("rings")) region.rings.push_back(read_ints(ring));
      t.regions.push_back(std::move(region));
    }
    t.partners.x = read_pairs(j.at("partners").at("x"));
    t.partners.y = read_pairs(j.at("partners").at("y"));
    const Json& s = j.at("statistics");
    t.stats.grains = read_int(s.at("grains"));
    t.stats.sharpest_corner_deg = s.at("sharpest_corner_deg").get<double>();
    t.stats.shortest_edge = s.at("shortest_edge").get<double>();
    validate(t);
  } catch (const nlohmann::json::exception& e) {
    throw GeometryError(source + ": not a tessellation.json of grainmesh tessellate: " + json_error_text(e));
  } catch (const GeometryError& e) {
    throw GeometryError(source + ": " + e.what());
  }
  return t;
}

nlohmann::ordered_json phases_json(const Tessellation& t) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (std::size_t p = 0; p < t.phases.size(); ++p)
    out.push_back({{"name", t.phases[p].name},
                   {"target_fraction", t.stats.phases[p].target_fraction},
                   {"achieved_fraction", t.stats.phases[p].achieved_fraction},
                   {"grains", t.stats.phases[p].grains}});
  return out;
}

}  // namespace grainmesh
