// `grainmesh run`'s stages on a solid cell (cell_run.hpp).
#include <cstdio>
#include <optional>

#include "common/format.hpp"
#include "export/foam_case_3d.hpp"
#include "export/foam_load.hpp"
#include "pipelines/answer_summary.hpp"
#include "pipelines/cell_run.hpp"
#include "pipelines/directory.hpp"
#include "pipelines/mesh_outputs.hpp"
#include "pipelines/refined_mesh.hpp"
#include "pipelines/run_cases.hpp"
#include "pipelines/tessellation_outputs.hpp"
#include "view/picture.hpp"

namespace grainmesh {

namespace {

class SolidCellRun final : public CellRun {
 public:
  SolidCellRun(const RunPlan& plan, const CellJobs<3>& jobs)
      : plan_(plan), jobs_(jobs), foam_(plan.foam), unit_(length_unit_name(plan.foam.convert_to_meters)) {}

  void tessellate(Warnings& warnings) override {
    t_ = run_tessellate_job(jobs_.tessellate);
    check_phases(*t_, jobs_.tessellate, warnings);
  }

  void mesh(const StageLine& stage, Warnings& warnings) override {
    mesh_job_ = resolve_mesh_job(jobs_.mesh, *t_);
    mesh_job_.options.deadline = jobs_.tessellate.options.deadline;  // one guard for the whole run
    stage.show("meshing " + std::to_string(t_->regions.size()) + " regions");
    m_ = run_mesh_job(*t_, mesh_job_, warnings);
  }

  Json write_geometry(const std::filesystem::path& dir, Warnings& warnings) override {
    const Drawing drawing{.pictures = pictures(), .detail = false, .unit = unit_};
    Json fields = write_tessellation_files(dir, *t_, jobs_.tessellate, drawing, warnings);
    write_tessellation_viewer(dir, *t_);  // the grains as polyhedra: the sections show only a plane
    fields.update(write_mesh_files(dir, *t_, *m_, mesh_job_, drawing, warnings));  // section_z: the same
    section_z_ = fields["section_z"].get<double>();
    mesh_fields_ = fields["mesh"];
    return fields;
  }

  std::vector<std::string> write_cases(const std::filesystem::path& dir, Warnings& warnings) override {
    e_ = refined(grain_export_mesh(*t_, *m_), plan_.refine, mesh_job_.origin);
    if (plan_.formats.mesh_files())
      mesh_files_ = write_element_files(dir, element_mesh(*e_), plan_.formats, {.length_unit = unit_});
    foam_.binary = binary_case(plan_, e_->mesh.tets.size());
    std::vector<std::string> names = write_run_cases(dir, *e_, foam_, plan_.boundary, fm_);
    if (const auto& d = fm_.mending; d && (d->failing_faces > 0 || d->failing_cells > 0))
      warnings.add("export: " + std::to_string(d->failing_faces) + " faces and " + std::to_string(d->failing_cells) +
                   " cells of the dual polyhedra still fail checkMesh's limits after mending (skewness 4, "
                   "non-orthogonality 90 degrees; case_cells.dual_mending): OpenFOAM's answer is less accurate "
                   "there, the finite elements' (on the tetrahedra) not; export.cells = tetrahedra avoids it");
    return names;
  }

  Json case_fields() const override {
    Json fields{{"case_format", foam_.binary ? "binary" : "ascii"},
                {"case_cells",
                 {{"shape", foam_.cells == FoamOptions::Cells::polygons ? "polyhedra" : "tetrahedra"},
                  {"cells", fm_.mesh.cells},
                  {"faces", fm_.mesh.faces()}}}};
    if (const auto& d = fm_.mending)
      fields["case_cells"]["dual_mending"] = {{"folded_points", d->folded_points},
                                              {"joined_cells", d->joined_cells},
                                              {"failing_faces", d->failing_faces},
                                              {"failing_cells", d->failing_cells}};
    if (plan_.refine > 0) fields["refine"] = plan_.refine;
    if (!mesh_files_.empty()) fields["mesh_files"] = mesh_files_;
    return fields;
  }

  std::string solving() const override {
    if (!plan_.solve) return "homogenising with finite elements";
    return plan_.boundary == Boundary::mixed ? "solving with solidDisplacementFoam (1 case)"
                                             : "solving with solidDisplacementFoam (" + std::to_string(cases()) + " cases)";
  }

  std::size_t solved_cells() const override { return static_cast<std::size_t>(fm_.mesh.cells); }

  RunAnswer solve(const std::filesystem::path& dir, const StagedOutput& staged,
                  std::vector<std::string>& warnings) override {
    const SolveInput<3> in{.dir = dir, .staged = staged, .t = *t_, .e = *e_, .pm = fm_, .foam = foam_,
                           .deadline = jobs_.tessellate.options.deadline,
                           .picture_width = pictures() ? mesh_job_.picture_width : 0, .all_pictures = false,
                           .section_z = section_z_, .unit = unit_,
                           .fe_mesh = fe_mesh(), .refine = plan_.refine, .solver = plan_.solver,
                           .fe_mesh_file = pictures() && plan_.keep_cases};
    if (!plan_.solve) return homogenise_fe(in, warnings);
    return plan_.boundary == Boundary::mixed ? homogenise_mixed(in, warnings) : homogenise_periodic(in, warnings);
  }

  void print_summary(const std::filesystem::path& out, const RunSeconds& seconds,
                     const RunAnswer* answer) const override {
    print_tessellation_summary(*t_, seconds.tessellate);
    print_mesh_summary(*m_, mesh_fields_);
    const char* cases = plan_.boundary == Boundary::mixed ? "case/"
                        : foam_.delta_T == 0.0            ? "case_xx/ ... case_xy/ (six load cases)"
                                                          : "case_xx/ ... case_xy/, case_thermal/ (seven load cases)";
    std::string mended;
    if (const auto& d = fm_.mending) {
      mended = "; mended: " + std::to_string(d->folded_points) + " points folded, " + std::to_string(d->joined_cells) +
               " cells joined";
      if (d->failing_faces + d->failing_cells > 0)
        mended += ", " + std::to_string(d->failing_faces) + " faces and " + std::to_string(d->failing_cells) +
                  " cells still failing checkMesh's limits";
    }
    std::printf("  cases: %s (%d %s cells%s)\n", cases, fm_.mesh.cells,
                foam_.cells == FoamOptions::Cells::polygons ? "polyhedral" : "tetrahedral", mended.c_str());
    if (answer != nullptr) print_answer(std::get<CellAnswer<3>>(*answer));
    std::printf("  wrote %s/{%s}%s\n", out.string().c_str(), entry_list(out).c_str(),
                pictures() ? (" (sections z = " + to_text(section_z_) + ")").c_str() : "");
  }

 private:
  bool pictures() const { return plan_.pictures != Pictures::none; }
  // The finite elements' coarse level (fe_coarse_mesh); none when they do not solve.
  const ExportMesh<3>* fe_mesh() {
    if (!plan_.solves_fe()) return nullptr;
    fe_mesh_ = refined(grain_export_mesh(*t_, fe_coarse_mesh(*t_, mesh_job_, m_->mesh.tets.size())), plan_.refine,
                       mesh_job_.origin);
    return &*fe_mesh_;
  }
  // The periodic load cases' count: six, and the thermal one.
  int cases() const { return foam_.delta_T == 0.0 ? 6 : 7; }

  const RunPlan& plan_;
  const CellJobs<3>& jobs_;
  FoamOptions foam_;  // the plan's, the case's format decided by its size
  std::string unit_;  // the pictures' scale bars
  MeshJob<3> mesh_job_;
  std::optional<Tessellation3> t_;
  std::optional<GrainMesh3> m_;
  std::optional<ExportMesh<3>> e_;
  std::optional<ExportMesh<3>> fe_mesh_;
  FoamMesh3 fm_;
  double section_z_ = 0.0;
  Json mesh_fields_;
  std::vector<std::string> mesh_files_;  // mesh.msh, mesh.inp as export.format asks
};

}  // namespace

std::unique_ptr<CellRun> make_cell_run(const RunPlan& plan, const CellJobs<3>& jobs) {
  return std::make_unique<SolidCellRun>(plan, jobs);
}

}  // namespace grainmesh
