#include "pipelines/report_read.hpp"

#include <string>
#include <utility>

#include "analysis/engineering.hpp"
#include "common/errors.hpp"

namespace grainmesh {

namespace {

// A schema-1 2D stiffness {C11, C22, C12, C21, C66, C16, C26, C61, C62} (as solved) as its
// symmetric part, named row by row {C11, C12, C16, C22, C26, C66}; a 3D one is kept.
Json symmetric_stiffness(const Json& c) {
  if (!c.is_object() || !c.contains("C21")) return c;
  const auto mean = [&](const char* a, const char* b) {
    return 0.5 * (c.at(a).get<double>() + c.at(b).get<double>());
  };
  return Json{{"C11", c.at("C11")}, {"C12", mean("C12", "C21")}, {"C16", mean("C16", "C61")},
              {"C22", c.at("C22")}, {"C26", mean("C26", "C62")}, {"C66", c.at("C66")}};
}

// {a11, a22, a12} as {xx, yy, xy}.
Json expansion_names(const Json& a) {
  if (!a.is_object() || !a.contains("a11")) return a;
  return Json{{"xx", a.at("a11")}, {"yy", a.at("a22")}, {"xy", a.at("a12")}};
}

void upgrade_effective(Json& e) {
  if (e.contains("stiffness") && !e.contains("solver")) e["solver"] = "openfoam";  // the only one there was
  for (const char* key : {"stiffness", "voigt", "reuss"})
    if (e.contains(key)) e[key] = symmetric_stiffness(e[key]);
  if (e.contains("volume_average") && e["volume_average"].contains("stiffness"))
    e["volume_average"]["stiffness"] = symmetric_stiffness(e["volume_average"]["stiffness"]);
  if (e.contains("thermal_expansion")) e["thermal_expansion"] = expansion_names(e["thermal_expansion"]);
  if (e.contains("thermal") && e["thermal"].contains("levin")) e["thermal"]["levin"] = expansion_names(e["thermal"]["levin"]);
  if (e.contains("load_cases") && e["load_cases"].is_object()) {  // 3D: by name
    Json cases = Json::array();
    for (auto& [name, run] : e["load_cases"].items()) {
      Json c{{"name", name}};
      c.update(run);
      cases.push_back(std::move(c));
    }
    e["load_cases"] = std::move(cases);
  }
  e.erase("strain");  // 3D: each case's (engineering) strain, now in the cases
  if (e.contains("engineering") && e["engineering"].contains("universal_anisotropy")) {
    e["anisotropy"] = {{"universal", e["engineering"]["universal_anisotropy"]}};
    e["engineering"].erase("universal_anisotropy");
  }
  // 2D: the universal anisotropy index, which schema 1 did not give, from the stiffness.
  if (e.contains("anisotropy") && !e["anisotropy"].contains("universal") && e.contains("stiffness")) {
    const Json& c = e["stiffness"];
    const auto at = [&](const char* name) { return c.at(name).get<double>(); };
    const Stiffness<3> C{{{at("C11"), at("C12"), at("C16")}, {at("C12"), at("C22"), at("C26")}, {at("C16"), at("C26"), at("C66")}}};
    e["anisotropy"]["universal"] = engineering_constants(C).universal_anisotropy;
  }
}

// 2D {area_fraction, mean {xx, yy, zz, xy}, ...} as {volume_fraction, mean {xx, yy, zz,
// yz, xz, xy}, ...}.
void upgrade_phase_stresses(Json& s) {
  if (!s.contains("area_fraction")) return;
  Json renamed{{"volume_fraction", s["area_fraction"]}};
  for (auto& [key, value] : s.items())
    if (key == "mean")
      renamed["mean"] = {{"xx", value.at("xx")}, {"yy", value.at("yy")}, {"zz", value.at("zz")},
                         {"yz", 0.0},         {"xz", 0.0},         {"xy", value.at("xy")}};
    else if (key != "area_fraction")
      renamed[key] = value;
  s = std::move(renamed);
}

}  // namespace

Json upgrade_report(Json r) {
  Json out{{"command", r.value("command", "run")}, {"schema", 2}};
  if (r.contains("statistics") && r["statistics"].contains("phases")) {  // 3D
    r["phases"] = r["statistics"]["phases"];
    r["statistics"].erase("phases");
  }
  if (r.contains("command") && (r["command"] == "run" || r["command"] == "tessellate" || r["command"] == "mesh"))
    out["dimensions"] = r.contains("depth") || (r.contains("pairs") && r["pairs"].contains("z")) ? 3 : 2;
  if (r.contains("effective")) {
    upgrade_effective(r["effective"]);
    // 2D: the bounds were those of the phases' achieved fractions.
    if (r["effective"].contains("stiffness") && !r["effective"].contains("volume_fractions") && r.contains("phases")) {
      Json fractions = Json::array();
      for (const Json& p : r["phases"]) fractions.push_back(p.at("achieved_fraction"));
      r["effective"]["volume_fractions"] = fractions;
    }
  }
  if (r.contains("stresses"))
    for (auto& [load, phases] : r["stresses"].items())
      for (auto& [phase, s] : phases.items()) upgrade_phase_stresses(s);
  for (auto& [key, value] : r.items())
    if (!out.contains(key)) out[key] = value;
  return out;
}

Json read_report(const std::filesystem::path& file) {
  Json r = read_json(file);
  if (!r.is_object()) throw IoError(file.string() + ": not a grainmesh report (no JSON object)");
  if (!r.contains("schema")) return upgrade_report(std::move(r));
  if (r["schema"] != kReportSchema)
    throw IoError(file.string() + ": report schema " + r["schema"].dump() + " is not one this grainmesh reads (" +
                  std::to_string(kReportSchema) + " and the unversioned schema 1); collect it with the grainmesh "
                  "that wrote it");
  // Written before homogenise.solver: OpenFOAM's answer.
  if (r.contains("effective") && r["effective"].contains("stiffness") && !r["effective"].contains("solver"))
    r["effective"]["solver"] = "openfoam";
  return r;
}

}  // namespace grainmesh
