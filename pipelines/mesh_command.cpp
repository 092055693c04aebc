#include "pipelines/mesh_command.hpp"

#include <cstdio>
#include <string>
#include <type_traits>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "grains/conformity.hpp"
#include "pipelines/mesh_outputs.hpp"
#include "pipelines/drawing.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/report.hpp"
#include "tessellate/tessellation_json.hpp"
#include "view/vtu.hpp"

namespace grainmesh {

Tessellation read_tessellation_file(const std::filesystem::path& file) {
  return tessellation_from_json<2>(read_text_file(file, "tessellation file"), file.string());
}

namespace {

template <class T>
void mesh_cell(const T& t, const std::filesystem::path& tessellation, const Config& c, const std::filesystem::path& out) {
  const auto job = read_mesh_job(c, t);
  Warnings warnings;
  const auto m = run_mesh_job(t, job, warnings);

  StagedOutput staged(out, "mesh");
  Json report{{"dimensions", std::is_same_v<T, Tessellation3> ? 3 : 2},
              {"tessellation", tessellation.string()},
              {"grains", t.stats.grains},
              {"regions", t.regions.size()}};
  report.update(write_mesh_files(staged.dir(), t, m, job, stage_drawing(c), warnings));
  report["seconds"] = m.seconds;
  report = finish_stage(staged, std::move(report), job.deadline(), warnings);
  print_mesh_summary(m, report["mesh"]);
  print_written(out, report);
}

}  // namespace

void run_mesh_command(const std::filesystem::path& tessellation, const Config& c, const std::filesystem::path& out) {
  claim_output(out, "mesh");
  const std::string text = read_text_file(tessellation, "tessellation file");
  if (tessellation_version(text) == 2) return mesh_cell(tessellation_from_json<3>(text, tessellation.string()), tessellation, c, out);
  mesh_cell(tessellation_from_json<2>(text, tessellation.string()), tessellation, c, out);
}

void run_check_command(const std::filesystem::path& tessellation, const std::filesystem::path& mesh_file) {
  const Tessellation t = read_tessellation_file(tessellation);
  VtuContents vtu = read_vtu(mesh_file);
  auto cell_ints = [&](const std::string& name) {
    if (const std::vector<int>* v = vtu.ints(name)) return *v;
    throw IoError(mesh_file.string() + ": no integer cell array '" + name + "' (is it a grainmesh mesh.vtu?)");
  };
  LabelledCells m{std::move(vtu.mesh), cell_ints("grain"), cell_ints("phase"), {}};
  Conformity c;
  try {
    validate(m.mesh);
    m.pairs = pair_periodic_nodes(t, m.mesh.points);
    c = check_conformity(t, m);
  } catch (const GeometryError& e) {
    throw GeometryError(mesh_file.string() + ": " + e.what());
  }
  const bool triangles = as_triangles(m.mesh).has_value();
  std::printf("grainmesh check: %s conforms to %s: %zu %s, grain areas within %.1e, %zu + %zu periodic node "
              "pairs within %.1e, %zu edges on the cell's sides\n",
              mesh_file.string().c_str(), tessellation.string().c_str(), m.mesh.cells(),
              triangles ? "triangles" : "polygonal cells", c.max_area_error,
              m.pairs.axis[0].size(), m.pairs.axis[1].size(), c.max_pair_mismatch, c.boundary_edges);
}

}  // namespace grainmesh
