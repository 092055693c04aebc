#include "view/mesh_description.hpp"

#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "common/json_error.hpp"
#include "common/text_file.hpp"

namespace grainmesh {

using Json = nlohmann::ordered_json;

void write_mesh_description(const std::filesystem::path& file, const MeshDescription& d) {
  Json phases = Json::array();
  for (const auto& p : d.phases) {
    Json j{{"name", p.name}};
    j["E"] = p.youngs_modulus ? Json(*p.youngs_modulus) : Json(nullptr);
    j["nu"] = p.poisson_ratio ? Json(*p.poisson_ratio) : Json(nullptr);
    phases.push_back(j);
  }
  write_text_file(file, Json{{"format", "grainmesh-mesh"},
                        {"version", 1},
                        {"cell",
                         {{"x0", d.cell.lo.x},
                          {"y0", d.cell.lo.y},
                          {"width", d.cell.width()},
                          {"height", d.cell.height()},
                          {"periodic", d.periodic}}},
                        {"phases", phases}}
                             .dump(2) +
                         "\n");
}

MeshDescription read_mesh_description(const std::filesystem::path& file) {
  const std::string text = read_text_file(file, "the mesh description (grainmesh mesh and domain write it beside mesh.vtu)");
  MeshDescription d;
  try {
    const Json j = Json::parse(text);
    if (j.at("format") != "grainmesh-mesh" || j.at("version") != 1)
      throw GeometryError(file.string() + ": not a grainmesh-mesh version 1 file");
    const Json& c = j.at("cell");
    const Vec2 lo{c.at("x0").get<double>(), c.at("y0").get<double>()};
    d.cell = Box{lo, lo + Vec2{c.at("width").get<double>(), c.at("height").get<double>()}};
    d.periodic = c.at("periodic").get<bool>();
    for (const Json& p : j.at("phases")) {
      MeshDescription::PhaseInfo info{p.at("name").get<std::string>(), {}, {}};
      if (p.contains("E") && !p["E"].is_null()) info.youngs_modulus = p["E"].get<double>();
      if (p.contains("nu") && !p["nu"].is_null()) info.poisson_ratio = p["nu"].get<double>();
      d.phases.push_back(info);
    }
  } catch (const Json::exception& e) {
    throw GeometryError(file.string() + ": not a mesh.json of grainmesh mesh or domain: " + json_error_text(e));
  }
  if (d.cell.empty() || d.phases.empty()) throw GeometryError(file.string() + ": no cell or no phases");
  return d;
}

}  // namespace grainmesh
