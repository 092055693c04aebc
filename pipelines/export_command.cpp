#include "pipelines/export_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <variant>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json_error.hpp"
#include "export/foam_case.hpp"
#include "mesh/quality.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/element_files.hpp"
#include "pipelines/material_units.hpp"
#include "pipelines/report.hpp"
#include "view/mesh_description.hpp"
#include "view/picture.hpp"
#include "view/vtu.hpp"

namespace grainmesh {

const std::vector<std::string>& export_config_keys() {
  static const std::vector<std::string> keys = keys_of(kExportKey);
  return keys;
}

FoamOptions read_foam_options(const Config& c) {
  c.check_keys(export_config_keys());
  FoamOptions o;
  o.thickness = c.number("export.thickness", 0.0);
  if (!(o.thickness >= 0.0) || !std::isfinite(o.thickness))
    c.fail("export.thickness", "must be positive (or 0 for the mean edge length), got " + c.text("export.thickness"));
  o.convert_to_meters = c.number("export.convert_to_meters", o.convert_to_meters);
  if (!(o.convert_to_meters > 0.0) || !std::isfinite(o.convert_to_meters))
    c.fail("export.convert_to_meters", "must be positive, got " + c.text("export.convert_to_meters"));
  o.cyclic = c.flag("export.cyclic", false);
  o.binary = read_export_formats(c).binary.value_or(false);
  o.grain_zones = c.flag("export.grain_zones", false);
  const std::string cells = c.has("export.cells") ? c.text("export.cells") : "triangles";
  if (cells != "triangles" && cells != "polygons") c.fail("export.cells", "must be triangles or polygons, got '" + cells + "'");
  o.cells = cells == "polygons" ? FoamOptions::Cells::polygons : FoamOptions::Cells::triangles;
  const std::string interp = c.has("export.stiffness_interpolation") ? c.text("export.stiffness_interpolation") : "auto";
  if (interp == "auto") o.interpolation = FoamOptions::Interpolation::automatic;
  else if (interp == "harmonic") o.interpolation = FoamOptions::Interpolation::harmonic;
  else if (interp == "linear") o.interpolation = FoamOptions::Interpolation::linear;
  else c.fail("export.stiffness_interpolation", "must be auto, harmonic or linear, got '" + interp + "'");
  o.displacement = c.number("load.displacement", o.displacement);
  if (!std::isfinite(o.displacement)) c.fail("load.displacement", "must be a finite number");
  o.traction = c.number("load.traction", 0.0);
  if (!std::isfinite(o.traction)) c.fail("load.traction", "must be a finite number");
  o.uniaxial = c.flag("load.uniaxial", false);
  o.plane_stress = c.flag("load.plane_stress", false);
  return o;
}

ExportMesh<2> read_export_mesh(const std::filesystem::path& mesh_file, const Config& c) {
  VtuContents vtu = read_vtu(mesh_file);
  std::filesystem::path json_file = mesh_file;
  json_file.replace_extension(".json");
  const MeshDescription d = read_mesh_description(json_file);
  ExportMesh<2> m;
  m.mesh = std::move(vtu.mesh);
  m.cell = d.cell;
  m.periodic = d.periodic;
  // A mesh read from a file: its periodic pairs from the nodes' exact coordinates.
  if (m.periodic) {
    try {
      m.pairs = pair_by_position(m.mesh.points, m.cell);
    } catch (const GeometryError& e) {
      throw GeometryError(mesh_file.string() + ": " + e.what());
    }
  }
  // Grain meshes carry grain and phase; domain meshes their region, which is the phase.
  const std::vector<int>* phase = vtu.ints("phase");
  const std::vector<int>* grain = vtu.ints("grain");
  const std::vector<int>* region = vtu.ints("region");
  if (!phase) phase = region;
  if (!grain) grain = phase;
  if (!phase) throw GeometryError(mesh_file.string() + ": no integer cell array 'phase' or 'region'");
  m.phase = *phase;
  m.grain = *grain;
  for (int p : m.phase)
    if (p < 0 || static_cast<std::size_t>(p) >= d.phases.size())
      throw GeometryError(mesh_file.string() + ": a cell has phase " + std::to_string(p) + ", but " + json_file.string() +
                          " names " + std::to_string(d.phases.size()));
  for (const std::string& name : c.names_in("phase")) {
    bool known = false;
    for (const auto& p : d.phases) known = known || p.name == name;
    if (!known) c.fail("phase." + name + (c.has("phase." + name + ".E") ? ".E" : ".nu"), "the mesh has no phase named '" + name + "'");
  }
  for (const auto& p : d.phases) {
    const std::string key = "phase." + p.name;
    FoamPhase fp{p.name, c.has(key + ".E") ? c.number(key + ".E") : p.youngs_modulus.value_or(NAN),
                 c.has(key + ".nu") ? c.number(key + ".nu") : p.poisson_ratio.value_or(NAN)};
    if (std::isnan(fp.youngs_modulus)) c.fail(key + ".E", "missing: the mesh does not give this phase's Young's modulus");
    if (std::isnan(fp.poisson_ratio)) c.fail(key + ".nu", "missing: the mesh does not give this phase's Poisson ratio");
    if (!(fp.youngs_modulus > 0.0) || !std::isfinite(fp.youngs_modulus))
      c.fail(key + ".E", "must be positive, got " + to_text(fp.youngs_modulus));
    if (c.has(key + ".E")) check_modulus_unit(c, key + ".E", fp.youngs_modulus);
    if (!(fp.poisson_ratio > -1.0 && fp.poisson_ratio < 0.5))
      c.fail(key + ".nu", "must lie in (-1, 0.5), got " + to_text(fp.poisson_ratio));
    m.phases.push_back(fp);
  }
  return m;
}

void run_export_command(const std::filesystem::path& mesh_file, const Config& c, const std::filesystem::path& out) {
  claim_output(out, "export");
  const FoamOptions o = read_foam_options(c);
  const ExportMesh<2> read = read_export_mesh(mesh_file, c);
  // A file of polygonal cells (an earlier export's mesh.vtu) is written as it is.
  const bool triangles = as_triangles(read.mesh).has_value();
  if (!triangles && o.cells == FoamOptions::Cells::triangles)
    c.fail("export.cells", "is triangles, but " + mesh_file.string() + " holds polygonal cells: set polygons to export them as they are");
  const ExportMesh<2> m = o.cells == FoamOptions::Cells::polygons && triangles ? polygon_cells(read) : read;
  const ExportFormats formats = read_export_formats(c);
  if (formats.mesh_files() && !triangles)
    c.fail("export.format", "gmsh and abaqus files take triangles, but " + mesh_file.string() + " holds polygonal cells");
  Warnings warnings;
  for (const std::string& w : check_load(foam_cell(m), o)) warnings.add(w);
  const auto start = std::chrono::steady_clock::now();
  StagedOutput staged(out, "export");
  write_foam_case(staged.dir(), m, o);
  // The same cells for VTK readers: cell k of the case is cell k (the triangles' quality
  // with them).
  std::vector<CellField> fields{{"grain", m.grain}, {"phase", m.phase}};
  if (const std::optional<TriMesh> tri = as_triangles(m.mesh)) fields.push_back({"quality", triangle_quality(*tri)});
  write_vtu(staged.dir() / "mesh.vtu", m.mesh, fields);
  const std::vector<std::string> mesh_files =
      formats.mesh_files() ? write_element_files(staged.dir(), element_mesh(read), formats,
                                                 {.plane_stress = o.plane_stress, .length_unit = length_unit_name(o.convert_to_meters)})
                           : std::vector<std::string>{};
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<int> cells_per_phase(m.phases.size(), 0);
  for (int p : m.phase) ++cells_per_phase[p];
  Json phases = Json::array();
  for (std::size_t p = 0; p < m.phases.size(); ++p)
    phases.push_back({{"name", m.phases[p].name},
                      {"E", m.phases[p].youngs_modulus},
                      {"nu", m.phases[p].poisson_ratio},
                      {"cells", cells_per_phase[p]}});
  Json report{{"mesh", mesh_file.string()},
              {"cells", m.mesh.cells()},
              {"points", 2 * m.mesh.points.size()},
              {"phases", phases},
              {"cyclic", o.cyclic && m.periodic},
              {"format", o.binary ? "binary" : "ascii"},
              {"mesh_files", mesh_files},
              {"convert_to_meters", o.convert_to_meters},
              {"load",
               {{"displacement", o.displacement},
                {"traction", o.traction},
                {"uniaxial", o.uniaxial},
                {"plane_stress", o.plane_stress}}},
              {"seconds", seconds},
              {"peak_memory_mib", peak_memory_mib()}};
  write_report(staged, report, warnings);
  staged.commit();
  std::printf("grainmesh export: %zu cells in %zu phases (%.3f s)\n  wrote the case %s (Allrun runs checkMesh and "
              "solidDisplacementFoam; open case.foam in ParaView)\n",
              m.mesh.cells(), m.phases.size(), seconds, out.string().c_str());
}

}  // namespace grainmesh
