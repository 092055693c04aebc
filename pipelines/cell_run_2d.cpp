// `grainmesh run`'s stages on a plane cell (cell_run.hpp).
#include <cstdio>
#include <optional>

#include "export/export_mesh.hpp"
#include "export/foam_case.hpp"
#include "export/foam_load.hpp"
#include "export/polymesh.hpp"
#include "pipelines/answer_summary.hpp"
#include "pipelines/cell_run.hpp"
#include "pipelines/directory.hpp"
#include "pipelines/refined_mesh.hpp"
#include "pipelines/run_cases.hpp"
#include "pipelines/mesh_outputs.hpp"
#include "pipelines/result_pictures.hpp"
#include "pipelines/tessellation_outputs.hpp"
#include "view/picture.hpp"

namespace grainmesh {

namespace {

class PlaneCellRun final : public CellRun {
 public:
  PlaneCellRun(const RunPlan& plan, const CellJobs<2>& jobs)
      : plan_(plan), jobs_(jobs), foam_(plan.foam), unit_(length_unit_name(plan.foam.convert_to_meters)) {}

  void tessellate(Warnings& warnings) override {
    t_ = run_tessellate_job(jobs_.tessellate);
    check_phases(*t_, jobs_.tessellate, warnings);
  }

  void mesh(const StageLine& stage, Warnings& warnings) override {
    mesh_job_ = resolve_mesh_job(jobs_.mesh, *t_);
    mesh_job_.options.distmesh.deadline = jobs_.tessellate.options.deadline;  // one guard for the whole run
    stage.show("meshing");
    if (stage.shown())
      mesh_job_.options.progress = [&](int done, int total) {
        stage.show("meshing: " + std::to_string(done) + " / " + std::to_string(total) + " regions", done == total);
      };
    m_ = run_mesh_job(*t_, mesh_job_, warnings);
    mesh_job_.options.progress = nullptr;
  }

  Json write_geometry(const std::filesystem::path& dir, Warnings& warnings) override {
    // No tessellation.vtp: mesh.vtu shows the grains.
    const Drawing drawing{.pictures = plan_.pictures != Pictures::none, .detail = plan_.pictures == Pictures::all,
                          .unit = unit_};
    Json fields = write_tessellation_files(dir, *t_, jobs_.tessellate, drawing, warnings);
    fields.update(write_mesh_files(dir, *t_, *m_, mesh_job_, drawing, warnings));
    mesh_fields_ = fields["mesh"];
    return fields;
  }

  std::vector<std::string> write_cases(const std::filesystem::path& dir, Warnings& /*warnings*/) override {
    if (plan_.refine == 0) {
      e_ = export_mesh(*t_, *m_, foam_.cells);
    } else {
      ExportMesh<2> triangles = refined(grain_export_mesh(*t_, *m_), plan_.refine, mesh_job_.origin);
      e_ = foam_.cells == FoamOptions::Cells::polygons ? polygon_cells(triangles) : std::move(triangles);
    }
    if (foam_.cells == FoamOptions::Cells::polygons && plan_.pictures == Pictures::all)
      // The solved cells, as mesh_detail.png shows the triangles.
      write_mesh_png(dir / "cells_detail.png", e_->mesh,
                     {.width_px = picture_width(), .fill_by = e_->phase, .outline_by = e_->grain,
                      .view = detail_view(*t_), .legend = phase_names(t_->phases), .scale_bar = true, .length_unit = unit_});
    if (plan_.formats.mesh_files()) {
      // The triangles the case is made of (its polygons' triangles when it has polygons).
      const bool triangles = foam_.cells == FoamOptions::Cells::triangles;
      const ElementMesh elements = triangles ? element_mesh(*e_)
                                             : element_mesh(refined(grain_export_mesh(*t_, *m_), plan_.refine,
                                                                    mesh_job_.origin));
      mesh_files_ = write_element_files(dir, elements, plan_.formats,
                                        {.plane_stress = foam_.plane_stress, .length_unit = unit_});
    }
    foam_.binary = binary_case(plan_, e_->mesh.cells());
    return write_run_cases(dir, *e_, foam_, plan_.boundary, pm_);
  }

  Json case_fields() const override {
    Json fields{{"case_format", foam_.binary ? "binary" : "ascii"}, {"plane_state", plane_state(foam_)}};
    // Polygonal or refined cells: how many the case has (mesh.cells counts the triangles as meshed).
    if (foam_.cells == FoamOptions::Cells::polygons || plan_.refine > 0)
      fields["case_cells"] = {{"shape", foam_.cells == FoamOptions::Cells::polygons ? "polygons" : "triangles"},
                              {"cells", e_->mesh.cells()}};
    if (plan_.refine > 0) fields["refine"] = plan_.refine;
    if (!mesh_files_.empty()) fields["mesh_files"] = mesh_files_;
    return fields;
  }

  std::string solving() const override {
    return plan_.solve ? "solving with solidDisplacementFoam" : "homogenising with finite elements";
  }

  std::size_t solved_cells() const override { return e_->mesh.cells(); }

  RunAnswer solve(const std::filesystem::path& dir, const StagedOutput& staged,
                  std::vector<std::string>& warnings) override {
    // The finite elements' coarse level (fe_coarse_mesh).
    std::optional<ExportMesh<2>> coarse;
    if (plan_.solves_fe())
      coarse = refined(grain_export_mesh(*t_, fe_coarse_mesh(*t_, mesh_job_, m_->mesh.triangles.size())), plan_.refine,
                       mesh_job_.origin);
    const SolveInput<2> in{.dir = dir, .staged = staged, .t = *t_, .e = *e_, .pm = pm_, .foam = foam_,
                           .deadline = jobs_.tessellate.options.deadline, .picture_width = picture_width(),
                           .all_pictures = plan_.pictures == Pictures::all, .section_z = 0.0, .unit = unit_,
                           .fe_mesh = coarse ? &*coarse : nullptr, .refine = plan_.refine, .solver = plan_.solver,
                           .fe_mesh_file = plan_.pictures != Pictures::none && plan_.keep_cases};
    if (!plan_.solve) return homogenise_fe(in, warnings);
    return plan_.boundary == Boundary::mixed ? homogenise_mixed(in, warnings) : homogenise_periodic(in, warnings);
  }

  void print_summary(const std::filesystem::path& out, const RunSeconds& seconds,
                     const RunAnswer* answer) const override {
    std::printf("grainmesh run: %d grains, %zu cells (q_min %.3f, q_mean %.3f), %.2f s\n  wrote %s/{%s}\n  each case's "
                "Allrun runs checkMesh and solidDisplacementFoam\n",
                t_->stats.grains, m_->mesh.triangles.size(), mesh_fields_["q_min"].get<double>(),
                mesh_fields_["q_mean"].get<double>(), seconds.total, out.string().c_str(), entry_list(out).c_str());
    if (answer != nullptr) print_answer(std::get<CellAnswer<2>>(*answer));
  }

 private:
  // The pictures' width in pixels; 0 for none.
  int picture_width() const { return plan_.pictures != Pictures::none ? mesh_job_.picture_width : 0; }

  const RunPlan& plan_;
  const CellJobs<2>& jobs_;
  FoamOptions foam_;  // the plan's, the case's format decided by its size
  std::string unit_;  // the pictures' scale bars
  MeshJob<2> mesh_job_;
  std::optional<Tessellation> t_;
  std::optional<GrainMesh> m_;
  std::optional<ExportMesh<2>> e_;
  PolyMesh pm_;
  Json mesh_fields_;  // report.json's mesh
  std::vector<std::string> mesh_files_;  // mesh.msh, mesh.inp as export.format asks
};

}  // namespace

std::unique_ptr<CellRun> make_cell_run(const RunPlan& plan, const CellJobs<2>& jobs) {
  return std::make_unique<PlaneCellRun>(plan, jobs);
}

}  // namespace grainmesh
