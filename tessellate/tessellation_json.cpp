#include "tessellate/tessellation_json.hpp"

#include <climits>
#include <cmath>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "common/json_error.hpp"
#include "tessellate/tessellation_3d.hpp"
#include "tessellate/validate.hpp"
#include "tessellate/validate_3d.hpp"

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

Json point(Vec3 p) { return Json::array({p.x, p.y, p.z}); }
Vec3 read_point3(const Json& j) {
  if (!j.is_array() || j.size() != 3) throw GeometryError("expected a point [x, y, z], found " + j.dump());
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

Json phases_list(const std::vector<Phase>& phases) {
  Json out = Json::array();
  for (const Phase& p : phases) {
    out.push_back({{"name", p.name}, {"target_fraction", p.fraction}, {"rest", p.rest},
                   {"E", p.youngs_modulus}, {"nu", p.poisson_ratio}});
    if (p.alpha) out.back()["alpha"] = *p.alpha;
  }
  return out;
}

std::vector<Phase> read_phases(const Json& j) {
  std::vector<Phase> phases;
  for (const Json& p : j) {
    phases.push_back(Phase{p.at("name").get<std::string>(), p.at("target_fraction").get<double>(),
                           p.at("rest").get<bool>(), p.at("E").get<double>(), p.at("nu").get<double>(), {}});
    if (p.contains("alpha")) phases.back().alpha = p.at("alpha").get<double>();
  }
  return phases;
}

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

// Parses a tessellation.json, its format and version checked: `version` (1: 2D, 2: 3D)
// wanted, the other one named. Then `read` fills the result; every error, the JSON
// library's too, becomes one GeometryError starting with `source`.
template <typename T, typename Read>
T read_tessellation(const std::string& text, const std::string& source, int version, Read read) {
  try {
    const Json j = Json::parse(text);
    if (j.value("format", "") != "grainmesh-tessellation")
      throw GeometryError("not a grainmesh tessellation (format key)");
    const int found = read_int(j.at("version"));
    if (found == 3 - version)
      throw GeometryError(version == 1 ? "a 3D tessellation (version 2), where a 2D one is needed"
                                       : "a 2D tessellation (version 1), where a 3D one is needed");
    if (found != version) throw GeometryError("tessellation version " + j.at("version").dump() + " is not supported");
    return read(j);
  } catch (const nlohmann::json::exception& e) {
    throw GeometryError(source + ": not a tessellation.json of grainmesh tessellate: " + json_error_text(e));
  } catch (const GeometryError& e) {
    throw GeometryError(source + ": " + e.what());
  }
}

}  // namespace

std::string tessellation_to_json(const Tessellation& t) {
  Json j;
  j["format"] = "grainmesh-tessellation";
  j["version"] = 1;
  j["domain"] = {{"width", t.width}, {"height", t.height}, {"periodic", t.periodic}};
  j["phases"] = phases_list(t.phases);
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
  j["partners"] = {{"x", t.partners.axis[0]}, {"y", t.partners.axis[1]}};
  j["statistics"] = statistics_json(t);
  return j.dump(1) + "\n";
}

Json statistics_json(const Tessellation& t) {
  Json j = statistics(t.stats, t.phases);
  j.update(descriptors_json(t.phases, t.stats.phases));
  return j;
}

Json descriptors_json(const std::vector<Phase>& phases, const std::vector<PhaseStats>& stats) {
  auto value = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  Json out;
  for (const char* key : {"contiguity", "intercept_length", "mean_free_path"}) out[key] = Json::object();
  for (std::size_t p = 0; p < phases.size() && p < stats.size(); ++p) {
    const PhaseStats& s = stats[p];
    out["contiguity"][phases[p].name] = value(s.contiguity);
    out["intercept_length"][phases[p].name] = value(s.intercept_length);
    out["mean_free_path"][phases[p].name] = value(s.mean_free_path);
  }
  return out;
}

template <>
Tessellation tessellation_from_json<2>(const std::string& text, const std::string& source) {
  return read_tessellation<Tessellation>(text, source, 1, [](const Json& j) {
    Tessellation t;
    const Json& d = j.at("domain");
    t.width = d.at("width").get<double>();
    t.height = d.at("height").get<double>();
    t.periodic = d.at("periodic").get<bool>();
    t.phases = read_phases(j.at("phases"));
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
    t.partners.axis[0] = read_pairs(j.at("partners").at("x"));
    t.partners.axis[1] = read_pairs(j.at("partners").at("y"));
    const Json& s = j.at("statistics");
    t.stats.grains = read_int(s.at("grains"));
    t.stats.sharpest_corner_deg = s.at("sharpest_corner_deg").get<double>();
    t.stats.shortest_edge = s.at("shortest_edge").get<double>();
    validate(t);
    return t;
  });
}

nlohmann::ordered_json phases_json(const Tessellation& t) { return phases_json(t.phases, t.stats.phases); }

nlohmann::ordered_json phases_json(const std::vector<Phase>& phases, const std::vector<PhaseStats>& stats) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (std::size_t p = 0; p < phases.size(); ++p)
    out.push_back({{"name", phases[p].name},
                   {"target_fraction", stats[p].target_fraction},
                   {"achieved_fraction", stats[p].achieved_fraction},
                   {"grains", stats[p].grains}});
  return out;
}

// --- version 2: 3D -------------------------------------------------------------------

int tessellation_version(const std::string& text) {
  const Json j = Json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("version") || !j["version"].is_number_integer()) return 0;
  return j["version"].get<int>();
}

std::string tessellation_to_json(const Tessellation3& t) {
  Json j;
  j["format"] = "grainmesh-tessellation";
  j["version"] = 2;
  j["domain"] = {{"width", t.width}, {"height", t.height}, {"depth", t.depth}, {"periodic", t.periodic}};
  j["phases"] = phases_list(t.phases);
  Json grains = Json::array();
  for (const Grain3& g : t.grains) {
    grains.push_back({{"id", g.id}, {"phase", g.phase}, {"seed", point(g.seed)}, {"volume", g.volume},
                      {"faces", g.faces}, {"neighbours", g.neighbours}});
    if (g.matrix) grains.back()["matrix"] = true;  // binder mode's matrix (absent: a grain)
  }
  j["grains"] = grains;
  Json vertices = Json::array();
  for (Vec3 v : t.vertices) vertices.push_back(point(v));
  j["vertices"] = vertices;
  Json faces = Json::array();
  for (const Face3& f : t.faces) faces.push_back({{"back", f.back}, {"front", f.front}, {"ring", f.ring}});
  j["faces"] = faces;
  Json regions = Json::array();
  for (const Region3& r : t.regions) regions.push_back({{"grain", r.grain}, {"phase", r.phase}, {"faces", r.faces}});
  j["regions"] = regions;
  j["partners"] = {{"x", t.partners.axis[0]}, {"y", t.partners.axis[1]}, {"z", t.partners.axis[2]}};
  j["statistics"] = statistics_json(t.stats, t.phases);
  return j.dump(1) + "\n";
}

nlohmann::ordered_json statistics_json(const Tessellation3& t) { return statistics_json(t.stats, t.phases); }

nlohmann::ordered_json statistics_json(const Tessellation3Stats& s, const std::vector<Phase>& phases) {
  Json j;
  j["grains"] = s.grains;
  j["removed_grains"] = s.removed_grains;
  j["volume_mean"] = s.volume_mean;
  j["volume_std"] = s.volume_std;
  j["diameter_mean"] = s.diameter_mean;
  j["diameter_std"] = s.diameter_std;
  j["faces_per_grain_mean"] = s.faces_per_grain_mean;
  j["neighbours_mean"] = s.neighbours_mean;
  j["shortest_edge"] = s.shortest_edge;
  j["smallest_face"] = s.smallest_face;
  j["sharpest_dihedral_deg"] = s.sharpest_dihedral_deg;
  j["edge_threshold"] = s.edge_threshold;
  j["collapsed_edges"] = s.collapsed_edges;
  j["removed_regions"] = s.removed_regions;
  j["shortest_edge_before"] = s.shortest_edge_before;
  j["sharpest_dihedral_before_deg"] = s.sharpest_dihedral_before_deg;
  j["window_origin"] = point(s.window_origin);
  if (s.binder_scale > 0.0) {  // binder mode only
    j["binder_scale"] = s.binder_scale;
    j["binder_contacts"] = s.binder_contacts;
    j["binder_layer"] = s.binder_layer;
  }
  j["phases"] = phases_json(phases, s.phases);
  j.update(descriptors_json(phases, s.phases));
  return j;
}

namespace {

double read_double_or_nan(const Json& j) { return j.is_null() ? std::nan("") : j.get<double>(); }

// statistics_json() read back, so a file read and written again has the same bytes.
Tessellation3Stats read_statistics(const Json& j, const std::vector<Phase>& phases) {
  Tessellation3Stats s;
  s.grains = read_int(j.at("grains"));
  s.removed_grains = read_int(j.at("removed_grains"));
  s.volume_mean = j.at("volume_mean").get<double>();
  s.volume_std = j.at("volume_std").get<double>();
  s.diameter_mean = j.at("diameter_mean").get<double>();
  s.diameter_std = j.at("diameter_std").get<double>();
  s.faces_per_grain_mean = j.at("faces_per_grain_mean").get<double>();
  s.neighbours_mean = j.at("neighbours_mean").get<double>();
  s.shortest_edge = j.at("shortest_edge").get<double>();
  s.smallest_face = j.at("smallest_face").get<double>();
  s.sharpest_dihedral_deg = j.at("sharpest_dihedral_deg").get<double>();
  s.edge_threshold = j.at("edge_threshold").get<double>();
  s.collapsed_edges = read_int(j.at("collapsed_edges"));
  s.removed_regions = read_int(j.at("removed_regions"));
  s.shortest_edge_before = j.at("shortest_edge_before").get<double>();
  s.sharpest_dihedral_before_deg = j.at("sharpest_dihedral_before_deg").get<double>();
  s.window_origin = read_point3(j.at("window_origin"));
  if (j.contains("binder_scale")) {
    s.binder_scale = j.at("binder_scale").get<double>();
    s.binder_contacts = read_int(j.at("binder_contacts"));
    s.binder_layer = j.at("binder_layer").get<double>();
  }
  const Json& ph = j.at("phases");
  if (!ph.is_array() || ph.size() != phases.size()) throw GeometryError("statistics: not one entry per phase");
  for (std::size_t p = 0; p < phases.size(); ++p) {
    PhaseStats ps;
    ps.target_fraction = ph[p].at("target_fraction").get<double>();
    ps.achieved_fraction = ph[p].at("achieved_fraction").get<double>();
    ps.grains = read_int(ph[p].at("grains"));
    ps.contiguity = read_double_or_nan(j.at("contiguity").at(phases[p].name));
    // Files from before 3D cells had them: not measured.
    ps.intercept_length = j.contains("intercept_length") ? read_double_or_nan(j["intercept_length"].at(phases[p].name))
                                                         : std::nan("");
    ps.mean_free_path = j.contains("mean_free_path") ? read_double_or_nan(j["mean_free_path"].at(phases[p].name))
                                                     : std::nan("");
    s.phases.push_back(ps);
  }
  return s;
}

}  // namespace

template <>
Tessellation3 tessellation_from_json<3>(const std::string& text, const std::string& source) {
  return read_tessellation<Tessellation3>(text, source, 2, [](const Json& j) {
    Tessellation3 t;
    const Json& d = j.at("domain");
    t.width = d.at("width").get<double>();
    t.height = d.at("height").get<double>();
    t.depth = d.at("depth").get<double>();
    t.periodic = d.at("periodic").get<bool>();
    t.phases = read_phases(j.at("phases"));
    for (const Json& g : j.at("grains")) {
      t.grains.push_back(Grain3{read_int(g.at("id")), read_int(g.at("phase")), read_point3(g.at("seed")),
                                g.at("volume").get<double>(), read_int(g.at("faces")), read_ints(g.at("neighbours")),
                                g.contains("matrix") && g.at("matrix").get<bool>()});
      if (t.grains.back().id != static_cast<int>(t.grains.size()) - 1) throw GeometryError("grain ids are not 0, 1, 2, ...");
      if (t.grains.back().phase < 0 || t.grains.back().phase >= static_cast<int>(t.phases.size()))
        throw GeometryError("a grain's phase is out of range");
    }
    for (const Json& v : j.at("vertices")) t.vertices.push_back(read_point3(v));
    for (const Json& f : j.at("faces"))
      t.faces.push_back(Face3{read_ints(f.at("ring")), read_int(f.at("back")), read_int(f.at("front"))});
    for (const Json& r : j.at("regions")) {
      t.regions.push_back(Region3{read_int(r.at("grain")), read_int(r.at("phase")), read_ints(r.at("faces")), 0.0});
      for (int f : t.regions.back().faces)
        if (f < 0 || f >= static_cast<int>(t.faces.size())) throw GeometryError("a region's face id is out of range");
      if (t.regions.back().faces.empty()) throw GeometryError("a region has no faces");
    }
    for (Region3& r : t.regions) r.volume = region_volume(t, r);
    const Json& p = j.at("partners");
    for (int a = 0; a < 3; ++a) t.partners.axis[a] = read_pairs(p.at(std::string(1, "xyz"[a])));
    for (const auto& pairs : t.partners.axis)
      for (const auto& [lo, hi] : pairs)
        if (lo < 0 || hi < 0 || lo >= static_cast<int>(t.vertices.size()) || hi >= static_cast<int>(t.vertices.size()))
          throw GeometryError("a partner id is out of range");
    t.stats = read_statistics(j.at("statistics"), t.phases);
    validate(t);
    return t;
  });
}

}  // namespace grainmesh
