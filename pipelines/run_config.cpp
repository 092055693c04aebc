#include "pipelines/run_config.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>

#include "pipelines/config_keys.hpp"
#include "pipelines/default_config.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/mesh_command.hpp"
#include "pipelines/tessellate_3d_command.hpp"
#include "pipelines/tessellate_command.hpp"

namespace grainmesh {

const std::vector<std::string>& run_own_config_keys() {
  static const std::vector<std::string> keys = keys_of(kRunKey);
  return keys;
}

Boundary read_boundary(const Config& c) {
  const std::string b = c.has("homogenise.boundary") ? c.text("homogenise.boundary") : "mixed";
  if (b == "mixed") return Boundary::mixed;
  if (b == "periodic") return Boundary::periodic;
  c.fail("homogenise.boundary", "must be mixed or periodic, got '" + b + "'");
}

Pictures read_pictures(const Config& c) {
  if (!c.has("output.pictures")) return Pictures::all;
  const std::string p = c.text("output.pictures");
  if (p == "none" || p == "false") return Pictures::none;
  if (p == "basic") return Pictures::basic;
  if (p == "all" || p == "true") return Pictures::all;
  c.fail("output.pictures", "must be none, basic or all, got '" + p + "'");
}

bool read_keep_cases(const Config& c, bool solve) {
  const std::string cases = c.has("output.cases") ? c.text("output.cases") : "keep";
  if (cases != "keep" && cases != "answers") c.fail("output.cases", "must be keep or answers, got '" + cases + "'");
  if (cases == "answers" && !solve)
    c.fail("output.cases", "answers keeps a solved run's answers and drops its cases: it needs --solve (without it, the "
                           "cases are what the run makes)");
  return cases == "keep";
}

void drop_cases(const std::filesystem::path& dir, const std::vector<std::string>& cases, Json& report) {
  for (const std::string& name : cases) std::filesystem::remove_all(dir / name);
  report["cases"] = "dropped once solved (output.cases = answers)";
}

std::vector<std::string> run_config_keys() {
  std::vector<std::string> keys = tessellate_config_keys();
  for (const auto& k : run_own_config_keys()) keys.push_back(k);
  for (const auto& k : mesh_config_keys()) keys.push_back(k);
  for (const auto& k : export_config_keys()) keys.push_back(k);
  return keys;
}

const char* default_run_config() { return kDefaultRunConfig; }

std::string config_ini(const Config& config, const std::vector<std::string>& notes) {
  // "a.b.c" is key c of section [a.b]; sections in order of first appearance.
  std::vector<std::string> order;
  std::map<std::string, std::string> body;
  for (const auto& [key, value] : config.entries()) {
    const auto dot = key.rfind('.');
    const std::string section = dot == std::string::npos ? "" : key.substr(0, dot);
    if (!body.count(section)) order.push_back(section);
    body[section] += key.substr(dot + 1) + " = " + value + "\n";
  }
  std::string text = "# The resolved config of a grainmesh run: `grainmesh run config.ini -o OUT` repeats it.\n";
  for (const std::string& note : notes) text += "# " + note + "\n";
  for (const std::string& s : order) text += "\n[" + s + "]\n" + body[s];
  return text;
}

std::string config_fingerprint(const Config& c) {
  std::string text;
  for (const auto& [key, value] : c.entries())
    if (key != "mesh.threads" && key != kTimeLimitKey) text += key + "=" + value + "\n";
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a, 64 bits
  for (const unsigned char ch : text) h = (h ^ ch) * 0x100000001b3ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

int read_solve_processes(const Config& c) {
  const long long processes = c.integer("solve.processes", 1);
  if (processes < 1 || processes > 1024) c.fail("solve.processes", "must be a count from 1 to 1024, got " + c.text("solve.processes"));
  return static_cast<int>(processes);
}

void check_periodic_cell(const Config& c) {
  if (!c.flag("domain.periodic", false))
    c.fail("homogenise.boundary", "periodic needs a periodic cell: set domain.periodic = true");
}

double read_delta_T(const Config& c) {
  const double delta_T = c.number("load.delta_T", 0.0);
  if (!std::isfinite(delta_T)) c.fail("load.delta_T", "must be a finite number (K), got " + c.text("load.delta_T"));
  if (delta_T != 0.0) {
    // Every phase's expansion, from the config (the tessellation reads the same keys).
    for (const std::string& name : c.names_in("phase")) {
      const std::string key = "phase." + name + ".alpha";
      if (!c.has(key))
        c.fail(key, "missing: load.delta_T = " + c.text("load.delta_T") +
                        " needs every phase's linear thermal expansion (1/K, e.g. 5e-6 for WC, 14e-6 for Co)");
      if (!(c.number(key) >= 0.0)) c.fail(key, "must be >= 0 (1/K), got " + c.text(key));
    }
    if (read_boundary(c) != Boundary::periodic)
      c.fail("load.delta_T", "needs homogenise.boundary = periodic: the thermal load is solved on a periodic cell, "
                             "free to expand on average");
  }
  return delta_T;
}

FoamOptions read_run_foam_options(const Config& c) {
  FoamOptions o = read_foam_options(c.subset(export_config_keys()));
  o.processes = read_solve_processes(c);
  o.delta_T = read_delta_T(c);
  if (read_boundary(c) != Boundary::periodic) return o;
  check_periodic_cell(c);
  for (const char* key : {"load.traction", "load.uniaxial"})
    if (c.has(key))
      c.fail(key, "not with homogenise.boundary = periodic, whose load cases are macroscopic strains (of "
                  "load.displacement / width)");
  if (c.has("export.cyclic") && !o.cyclic)
    c.fail("export.cyclic", "homogenise.boundary = periodic needs the cyclic pairs; remove export.cyclic = false");
  o.cyclic = true;
  return o;
}

void check_run_config(const Config& c) {
  c.check_keys(run_config_keys());
  if (cell_dimensions(c) == 3) return check_run_3d_config(c);
  read_pictures(c);
  read_tessellate_job(c.subset(tessellate_config_keys()));
  read_run_foam_options(c);
}

namespace {

// The export, load and solve keys a 3D run takes (beside the tessellation's and the mesh's).
const std::vector<std::string>& case_keys_3d() {
  static const std::vector<std::string> keys{"export.convert_to_meters", "export.format", "export.grain_zones",
                                             "export.cells", "load.displacement", "load.uniaxial", "load.delta_T",
                                             "homogenise.boundary", "solve.processes", "output.pictures", "output.cases"};
  return keys;
}

// Why a 2D key is refused on 3D cells.
std::string refused_3d(const std::string& key) {
  if (key == "export.thickness" || key == "load.plane_stress") return "a 3D cell has no plane to extrude or hold";
  if (key == "export.cyclic") return "homogenise.boundary = periodic makes the cyclic pairs";
  if (key == "export.stiffness_interpolation") return "3D cases interpolate the stiffness linearly (harmonic diverges)";
  if (key == "load.traction") return "3D cases are loaded by load.displacement";
  return "not available for 3D cells (domain.depth is set)";
}

}  // namespace

FoamOptions read_foam_options_3d(const Config& c) {
  std::vector<std::string> keys = export_config_keys();
  std::erase(keys, std::string("export.cells"));
  FoamOptions o = read_foam_options(c.subset(keys));
  const std::string cells = c.has("export.cells") ? c.text("export.cells") : "polyhedra";
  if (cells != "polyhedra" && cells != "tetrahedra")
    c.fail("export.cells", "must be polyhedra or tetrahedra on 3D cells, got '" + cells + "'");
  o.cells = cells == "polyhedra" ? FoamOptions::Cells::polygons : FoamOptions::Cells::triangles;
  o.processes = read_solve_processes(c);
  o.delta_T = read_delta_T(c);
  if (read_boundary(c) == Boundary::periodic) {
    check_periodic_cell(c);
    if (c.has("load.uniaxial"))
      c.fail("load.uniaxial", "not with homogenise.boundary = periodic, whose load cases are macroscopic strains");
    o.cyclic = true;
  }
  return o;
}

void check_run_3d_config(const Config& c) {
  // A 3D run's keys: the tessellation's, the mesh's and the case's.
  std::vector<std::string> keys = tessellate_config_keys();
  keys.insert(keys.end(), mesh_config_keys().begin(), mesh_config_keys().end());
  keys.insert(keys.end(), case_keys_3d().begin(), case_keys_3d().end());
  const Config taken = c.subset(keys);
  for (const auto& [key, value] : c.entries())
    if (!taken.has(key)) c.fail(key, refused_3d(key));
  read_foam_options_3d(c);
  read_pictures(c);
  read_tessellate_3d_job(c.subset(tessellate_config_keys()));
}

}  // namespace grainmesh
