#include "pipelines/tessellate_command.hpp"

#include <chrono>
#include <string>

#include "pipelines/config.hpp"
#include "pipelines/drawing.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/tessellation_outputs.hpp"

namespace grainmesh {

namespace {

template <int D>
void tessellate_cell(const Config& c, const std::filesystem::path& out) {
  claim_output(out, "tessellate");
  const TessellateJob<D> job = read_tessellate_job<D>(c);
  const auto start = std::chrono::steady_clock::now();
  const auto t = run_tessellate_job(job);
  Warnings warnings;
  check_phases(t, job, warnings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  StagedOutput staged(out, "tessellate");
  Json report{{"config", c.source()}};
  report.update(write_tessellation_files(staged.dir(), t, job, stage_drawing(c), warnings));
  write_tessellation_viewer(staged.dir(), t);
  report["seconds"] = seconds;
  report = finish_stage(staged, std::move(report), job.options.deadline, warnings);
  print_tessellation_summary(t, seconds);
  print_written(out, report);
}

}  // namespace

void run_tessellate_command(const Config& c, const std::filesystem::path& out) {
  return cell_dimensions(c) == 3 ? tessellate_cell<3>(c, out) : tessellate_cell<2>(c, out);
}

}  // namespace grainmesh
