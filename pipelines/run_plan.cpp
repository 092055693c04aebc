#include "pipelines/run_plan.hpp"

#include <cmath>

#include "export/foam_load.hpp"
#include "export/foam_material.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/run_config.hpp"

namespace grainmesh {

namespace {

Boundary read_boundary(const Config& c) {
  const std::string b = c.has("homogenise.boundary") ? c.text("homogenise.boundary") : "mixed";
  if (b == "mixed") return Boundary::mixed;
  if (b == "periodic") return Boundary::periodic;
  c.fail("homogenise.boundary", "must be mixed or periodic, got '" + b + "'");
}

bool read_keep_cases(const Config& c, bool solve) {
  const std::string cases = c.has("output.cases") ? c.text("output.cases") : "keep";
  if (cases != "keep" && cases != "answers") c.fail("output.cases", "must be keep or answers, got '" + cases + "'");
  if (cases == "answers" && !solve)
    c.fail("output.cases", "answers keeps a solved run's answers and drops its cases: it needs --solve (without it, the "
                           "cases are what the run makes)");
  return cases == "keep";
}

int read_solve_processes(const Config& c) {
  const long long processes = c.integer("solve.processes", 1);
  if (processes < 1 || processes > 1024) c.fail("solve.processes", "must be a count from 1 to 1024, got " + c.text("solve.processes"));
  return static_cast<int>(processes);
}

// homogenise.solver: where a periodic cell's answer comes from; the finite elements unless
// told otherwise (the mixed load is OpenFOAM's alone).
Solver read_solver(const Config& c) {
  const bool periodic = read_boundary(c) == Boundary::periodic;
  if (!c.has("homogenise.solver")) return periodic ? Solver::fe : Solver::openfoam;
  const std::string s = c.text("homogenise.solver");
  if (s != "openfoam" && s != "fe") c.fail("homogenise.solver", "must be openfoam or fe, got '" + s + "'");
  if (s == "fe" && !periodic)
    c.fail("homogenise.solver", "fe homogenises a periodic cell: it needs homogenise.boundary = periodic (the mixed "
                                "load is solved by OpenFOAM)");
  return s == "fe" ? Solver::fe : Solver::openfoam;
}

// homogenise.reference: whether the finite-element reference is solved beside the answer.
bool read_reference(const Config& c, bool solve) {
  const std::string r = c.has("homogenise.reference") ? c.text("homogenise.reference") : "none";
  if (r != "none" && r != "fe") c.fail("homogenise.reference", "must be none or fe, got '" + r + "'");
  if (r == "none") return false;
  if (read_boundary(c) != Boundary::periodic)
    c.fail("homogenise.reference", "fe needs homogenise.boundary = periodic: the reference homogenises a periodic cell");
  if (read_solver(c) == Solver::fe)
    c.fail("homogenise.reference", "fe is the answer already (homogenise.solver = fe; with --solve OpenFOAM's answer "
                                   "is put beside it): the reference is for homogenise.solver = openfoam");
  if (!solve) c.fail("homogenise.reference", "fe is solved beside the OpenFOAM load cases: it needs --solve");
  return true;
}

// mesh.refine: how often the mesh is split in nested refinement before the solves.
int read_refine(const Config& c) {
  const long long refine = c.integer("mesh.refine", 0);
  if (refine < 0 || refine > kMaxRefine)
    c.fail("mesh.refine", "must be a count from 0 to " + std::to_string(kMaxRefine) + ", got " + c.text("mesh.refine"));
  return static_cast<int>(refine);
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

// The export, load and solve keys a 3D run takes (beside the tessellation's and the mesh's).
const std::vector<std::string>& case_keys_3d() {
  static const std::vector<std::string> keys{"export.convert_to_meters", "export.format", "export.grain_zones",
                                             "export.cells", "load.displacement", "load.uniaxial", "load.delta_T",
                                             "homogenise.boundary", "homogenise.solver", "homogenise.reference", "solve.processes", "output.pictures",
                                             "output.cases", "mesh.refine", "export.plane_faces"};
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

// The case options of a run on a cell of `dimensions`: the export's keys (export.cells is
// polyhedra, the tetrahedra's dual and the default, or tetrahedra on a solid cell), the
// solver's processes, the temperature change; with homogenise.boundary = periodic the case
// is cyclic (refused on a cell that is not periodic, and with a traction or uniaxial load).
FoamOptions read_run_foam_options(const Config& c, int dimensions) {
  std::vector<std::string> keys = export_config_keys();
  if (dimensions == 3) std::erase(keys, std::string("export.cells"));
  FoamOptions o = read_foam_options(c.subset(keys));
  if (dimensions == 3) {
    const std::string cells = c.has("export.cells") ? c.text("export.cells") : "polyhedra";
    if (cells != "polyhedra" && cells != "tetrahedra")
      c.fail("export.cells", "must be polyhedra or tetrahedra on 3D cells, got '" + cells + "'");
    o.cells = cells == "polyhedra" ? FoamOptions::Cells::polygons : FoamOptions::Cells::triangles;
    o.plane_faces = c.flag("export.plane_faces", false);
    if (o.plane_faces && o.cells != FoamOptions::Cells::polygons)
      c.fail("export.plane_faces", "splits the faces of polyhedra; export.cells = tetrahedra has plane faces already");
  } else if (c.has("export.plane_faces")) {
    c.fail("export.plane_faces", "only for 3D cells' polyhedra (a 2D case's faces are plane)");
  }
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

// A 3D run's keys: the tessellation's, the mesh's and the case's; the 2D-only ones refused,
// each saying why.
void refuse_2d_keys(const Config& c) {
  std::vector<std::string> keys = tessellate_config_keys();
  keys.insert(keys.end(), mesh_config_keys().begin(), mesh_config_keys().end());
  keys.insert(keys.end(), case_keys_3d().begin(), case_keys_3d().end());
  const Config taken = c.subset(keys);
  for (const auto& [key, value] : c.entries())
    if (!taken.has(key)) c.fail(key, refused_3d(key));
}

// config.ini's note of what the defaults meant: the out-of-plane condition.
std::string plane_state_note(const FoamOptions& foam) {
  return std::string("2D: solved in ") + (foam.plane_stress ? "plane stress (load.plane_stress = true)"
                                                            : "plane strain (load.plane_stress = false, the default)");
}

}  // namespace

RunPlan read_run_plan(const Config& c, bool solve) {
  c.check_keys(run_config_keys());
  const int dimensions = cell_dimensions(c);
  if (dimensions == 3) refuse_2d_keys(c);
  RunPlan s;
  s.source = c.source();
  s.fingerprint = config_fingerprint(c);
  s.solve = solve;
  s.foam = read_run_foam_options(c, dimensions);
  if (solve && s.foam.traction != 0.0)
    c.fail("load.traction", "--solve homogenises under an imposed displacement; remove load.traction");
  const Config tess_config = c.subset(tessellate_config_keys()), mesh_config = c.subset(mesh_config_keys());
  if (dimensions == 3) {
    const auto& jobs = s.cell.emplace<CellJobs<3>>(CellJobs<3>{read_tessellate_job<3>(tess_config), read_mesh_job<3>(mesh_config)});
    const Tessellation3Options& o = jobs.tessellate.options;
    s.warnings = check_load(FoamCell{foam_phases(o.phases), {o.width, o.height, o.depth}, o.periodic}, s.foam);
    s.resolved_ini = config_ini(c);
  } else {
    const auto& jobs = s.cell.emplace<CellJobs<2>>(CellJobs<2>{read_tessellate_job<2>(tess_config), read_mesh_job<2>(mesh_config)});
    const TessellationOptions& o = jobs.tessellate.options;
    s.warnings = check_load(FoamCell{foam_phases(o.phases), {o.width, o.height, 0.0}, o.periodic}, s.foam);
    s.resolved_ini = config_ini(c, {plane_state_note(s.foam)});
  }
  s.formats = read_export_formats(c);
  s.boundary = read_boundary(c);
  s.solver = read_solver(c);
  s.fe_reference = read_reference(c, solve);
  s.refine = read_refine(c);
  s.pictures = read_pictures(c);
  s.keep_cases = read_keep_cases(c, solve);
  return s;
}

}  // namespace grainmesh
