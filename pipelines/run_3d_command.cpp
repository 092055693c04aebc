#include "pipelines/run_3d_command.hpp"

#include <unistd.h>

#include <cstdio>

#include "common/memory.hpp"
#include "pipelines/mesh_3d_command.hpp"
#include "pipelines/mesh_command.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "pipelines/run_config.hpp"
#include "pipelines/stage_line.hpp"
#include "pipelines/tessellate_3d_command.hpp"
#include "pipelines/tessellate_command.hpp"

namespace grainmesh {

void run_run_3d_command(const Config& c, const std::filesystem::path& out, bool solve, bool quiet, bool summary) {
  constexpr const char* kNotYet = "3D cells are not exported to OpenFOAM yet: grainmesh run tessellates and meshes them";
  if (solve) c.fail("domain.depth", std::string("--solve: ") + kNotYet);
  // A 3D run's keys: the tessellation's and the mesh's.
  std::vector<std::string> keys = tessellate_config_keys();
  keys.insert(keys.end(), mesh_config_keys().begin(), mesh_config_keys().end());
  const Config taken = c.subset(keys);
  for (const auto& [key, value] : c.entries())
    if (!taken.has(key)) c.fail(key, std::string("not available for 3D cells (domain.depth is set): ") + kNotYet);
  check_output_replaceable(out, "run");
  const Config tess_config = c.subset(tessellate_config_keys());
  const Tessellate3Job tess_job = read_tessellate_3d_job(tess_config);
  const auto start = Clock::now();
  StageLine stage(!quiet && isatty(STDERR_FILENO) != 0, start);
  Warnings warnings;
  Json seconds;

  auto clock = Clock::now();
  stage.show("tessellating");
  const Tessellation3 t = run_tessellate_3d_job(tess_job, tess_config, warnings);
  seconds["tessellate"] = since(clock);

  clock = Clock::now();
  Mesh3Job mesh_job = read_mesh_3d_job(c.subset(mesh_config_keys()), t);
  mesh_job.options.deadline = tess_job.options.deadline;  // one guard for the whole run
  stage.show("meshing " + std::to_string(t.regions.size()) + " regions");
  const GrainMesh3 m = run_mesh_3d_job(t, mesh_job);
  seconds["mesh"] = since(clock);
  stage.end();

  StagedOutput staged(out, "run");
  Json report{{"config", c.source()}, {"config_fingerprint", config_fingerprint(c)}};
  report.update(write_tessellation_3d_files(staged.dir(), t, tess_job));
  report.update(write_mesh_3d_files(staged.dir(), t, m, mesh_job, warnings));  // its grains and section_z: the same
  write_text_file(staged.dir() / "config.ini", config_ini(c));
  seconds["total"] = since(start);
  report["seconds"] = seconds;
  add_time_limit(report, tess_job.options.deadline);
  report["peak_memory_mib"] = peak_memory_mib();
  write_report(staged, report, warnings);
  staged.commit();
  if (!summary) return;
  print_tessellation_3d_summary(t, seconds["tessellate"].get<double>());
  print_mesh_3d_summary(report["mesh"], m.seconds);
  std::printf("  wrote %s/{tessellation.json, tessellation.vtu, tessellation.png, mesh.vtu, mesh.png (sections z = %g), "
              "config.ini, report.json}\n",
              out.string().c_str(), tess_job.section * t.depth);
}

}  // namespace grainmesh
