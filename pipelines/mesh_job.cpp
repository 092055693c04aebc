#include "pipelines/mesh_job.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/format.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/config_values.hpp"

namespace grainmesh {

namespace {

// Far too many tetrahedra is a slip (a unit, a digit): refused before any work is done.
constexpr double kMaxTets = 2e7;

// The keys a plane and a solid cell's mesh share: the size (mesh.size or mesh.h), or
// elements per grain under `per_grain_key` (`fallback` when neither is given, between
// `fewest` and 1e6); mesh.threads, output.picture_width and the time limit.
template <class Job>
void read_shared_keys(const Config& c, Job& job, const std::string& per_grain_key, double fallback, double fewest) {
  job.origin = c.origin();
  auto& o = job.options;
  const std::string size_key = one_of_keys(c, "mesh.size", "mesh.h");
  if (c.has(size_key) && c.has(per_grain_key))
    c.fail(per_grain_key, "give either " + size_key + " or " + per_grain_key + ", not both");
  if (c.has(size_key)) {
    o.size = c.number(size_key);
    if (!(o.size > 0.0) || !std::isfinite(o.size)) c.fail(size_key, "must be positive, got " + c.text(size_key));
    job.size_key = size_key;
  } else {
    job.per_grain = c.number(per_grain_key, fallback);
    if (!(*job.per_grain >= fewest && *job.per_grain <= 1e6))
      c.fail(per_grain_key, "must lie between " + to_text(fewest) + " and 1e6");
  }
  const long long threads = c.integer("mesh.threads", 0);
  if (threads < 0 || threads > 1024) c.fail("mesh.threads", "must be between 0 (all cores) and 1024");
  o.threads = static_cast<int>(threads);
  const long long width = c.integer("output.picture_width", job.picture_width);
  if (width < 100 || width > 20000) c.fail("output.picture_width", "must be between 100 and 20000");
  job.picture_width = static_cast<int>(width);
  const Deadline deadline = Deadline::after(read_time_limit(c), kTimeLimitKey);
  if constexpr (requires { o.distmesh; }) o.distmesh.deadline = deadline;
  else o.deadline = deadline;
}

}  // namespace

template <>
MeshJob<2> read_mesh_job<2>(const Config& c) {
  c.check_keys(mesh_config_keys());
  for (const char* key : {"mesh.tets_per_grain", "output.section"})
    if (c.has(key)) c.fail(key, "only for 3D tessellations (tessellation.json version 2)");
  MeshJob<2> job;
  read_shared_keys(c, job, "mesh.triangles_per_grain", 100.0, 2.0);
  GrainMeshOptions& o = job.options;
  // mesh.grading is the run config's name of mesh.gradient.
  const std::string gradient_key = one_of_keys(c, "mesh.gradient", "mesh.grading");
  for (const std::string& name : c.names_in("phase")) {
    const std::string key = "phase." + name + ".size";
    if (!c.has(key)) continue;
    job.phase_sizes.emplace_back(name, c.number(key));
    if (!(job.phase_sizes.back().second > 0.0) || !std::isfinite(job.phase_sizes.back().second))
      c.fail(key, "must be positive, got " + c.text(key));
  }
  for (const auto& [key, value] : {std::pair{"mesh.boundary_size", &o.boundary_size}, {"mesh.junction_size", &o.junction_size}}) {
    *value = c.number(key, 0.0);
    if (!(*value >= 0.0) || !std::isfinite(*value)) c.fail(key, "must be positive (or 0 for none), got " + c.text(key));
  }
  o.gradient = c.number(gradient_key, o.gradient);
  if (!(o.gradient >= 0.05 && o.gradient <= 10.0)) c.fail(gradient_key, "must lie between 0.05 and 10");
  o.seed = c.unsigned_integer("mesh.seed", 1);
  const long long iterations = c.integer("mesh.max_iterations", o.distmesh.max_iterations);
  if (iterations < 1 || iterations > 100'000'000) c.fail("mesh.max_iterations", "must be at least 1");
  o.distmesh.max_iterations = static_cast<int>(iterations);
  return job;
}

MeshJob<2> resolve_mesh_job(MeshJob<2> job, const Tessellation& t) {
  GrainMeshOptions& o = job.options;
  if (job.per_grain) {
    // Equilateral triangles of side h have area h^2 sqrt(3) / 4.
    const double grain_area = t.width * t.height / std::max(1, t.stats.grains);
    o.size = std::sqrt(4.0 * grain_area / (*job.per_grain * std::sqrt(3.0)));
  }
  o.phase_size.assign(t.phases.size(), 0.0);
  for (const auto& [name, size] : job.phase_sizes) {
    std::size_t p = 0;
    while (p < t.phases.size() && t.phases[p].name != name) ++p;
    if (p == t.phases.size()) {
      std::string names;
      for (const Phase& ph : t.phases) names += (names.empty() ? "" : ", ") + ph.name;
      job.origin.fail("phase." + name + ".size", "unknown phase '" + name + "' (the tessellation's phases: " + names + ")");
    }
    o.phase_size[p] = size;
  }
  // Far too fine a size is a slip (a unit, a digit): refused before any work is done.
  double finest = o.size;
  std::string finest_key = job.per_grain ? "mesh.triangles_per_grain" : job.size_key;
  for (std::size_t p = 0; p < t.phases.size(); ++p)
    if (o.phase_size[p] > 0.0 && o.phase_size[p] < finest) {
      finest = o.phase_size[p];
      finest_key = "phase." + t.phases[p].name + ".size";
    }
  const double triangles = t.width * t.height / (0.25 * std::sqrt(3.0) * finest * finest);
  if (triangles > 2.0 * kMaxMeshPoints) {
    job.origin.fail(finest_key, "asks for about " + to_text(triangles) + " triangles (size " + to_text(finest) + " over a " +
                                    to_text(t.width) + " x " + to_text(t.height) + " cell), more than " +
                                    to_text(2.0 * kMaxMeshPoints) + ": coarsen it");
  }
  return job;
}


template <>
MeshJob<3> read_mesh_job<3>(const Config& c) {
  for (const char* key : {"mesh.triangles_per_grain", "mesh.boundary_size", "mesh.junction_size", "mesh.gradient",
                          "mesh.grading", "mesh.seed", "mesh.max_iterations"})
    if (c.has(key)) c.fail(key, "not available for 3D meshes (mesh.size or mesh.tets_per_grain, mesh.threads)");
  for (const std::string& name : c.names_in("phase"))
    if (c.has("phase." + name + ".size")) c.fail("phase." + name + ".size", "not available for 3D meshes yet");
  MeshJob<3> job;
  read_shared_keys(c, job, "mesh.tets_per_grain", 500.0, 10.0);
  job.section = c.number("output.section", job.section);
  if (!(job.section > 0.0 && job.section < 1.0))
    c.fail("output.section", "must lie in (0, 1) (a fraction of the depth), got " + c.text("output.section"));
  return job;
}

MeshJob<3> resolve_mesh_job(MeshJob<3> job, const Tessellation3& t) {
  GrainMesh3Options& o = job.options;
  if (job.per_grain) {
    o.size = size_for_tets_per_grain(t, *job.per_grain);
    // Binder mode: the surfaces as fine as the binder layer is thick, the grains' cores
    // filled to the size asked for.
    if (t.stats.binder_layer > 0.0 && t.stats.binder_layer < o.size) {
      o.core_size = o.size;
      o.size = t.stats.binder_layer;
    }
  }
  double tets = t.width * t.height * t.depth / regular_tet_volume(o.core_size > 0.0 ? o.core_size : o.size);
  if (o.core_size > 0.0) {
    // Graded from the layer's surfaces: about ten tetrahedra per triangle of the grains'
    // area with the binder (2.03 million measured on 100 grains where this says 2.03).
    for (const Grain3& g : t.grains)
      if (g.matrix) tets += 10.0 * (2.0 * g.volume / t.stats.binder_layer) / (0.433 * o.size * o.size);
    if (tets > kMaxTets)
      job.origin.fail("mesh.tets_per_grain", "asks for about " + to_text(tets) + " tetrahedra, more than " +
                                                 to_text(kMaxTets) + ": binder mode meshes the surfaces as fine as the "
                                                 "binder layer is thick (" + to_text(t.stats.binder_layer, 3) +
                                                 "); fewer grains or more binder make fewer");
  }
  if (tets > kMaxTets)
    job.origin.fail(job.per_grain ? "mesh.tets_per_grain" : job.size_key,
                    "asks for about " + to_text(tets) + " tetrahedra, more than " + to_text(kMaxTets) + ": coarsen it");
  return job;
}

MeshJob<2> read_mesh_job(const Config& config, const Tessellation& t) { return resolve_mesh_job(read_mesh_job<2>(config), t); }
MeshJob<3> read_mesh_job(const Config& config, const Tessellation3& t) { return resolve_mesh_job(read_mesh_job<3>(config), t); }

MeshJob<2> scaled_mesh_job(MeshJob<2> job, double factor) {
  GrainMeshOptions& o = job.options;
  o.size *= factor;
  for (double& size : o.phase_size) size *= factor;
  o.boundary_size *= factor;
  o.junction_size *= factor;
  return job;
}

MeshJob<3> scaled_mesh_job(MeshJob<3> job, double factor) {
  job.options.size *= factor;
  return job;
}

}  // namespace grainmesh
