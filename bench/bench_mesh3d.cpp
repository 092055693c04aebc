// make bench: 3D cells of 100 and 1,000 Lloyd-relaxed periodic grains meshed at about 500
// tetrahedra per grain, each run in a fresh child process: seconds per stage (tessellate,
// surfaces, TetGen filling on all cores), peak memory, and the quality (radius ratio,
// dihedral angles; of the tetrahedra touching a grain surface and of the others apart),
// against Gmsh meshing the same polyhedra from a written .geo (one volume per region,
// shared surfaces; Gmsh's 3D Delaunay with its optimiser, 2 threads), and against Gmsh as
// the second filler of our own surfaces (its 3D Delaunay with its optimiser; Debian's Gmsh
// has no Netgen).
// Prints a table and writes bench/results.json ("mesh3d").
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "bench/child.hpp"
#include "bench/peers.hpp"
#include "grains3d/conformity_3d.hpp"
#include "grains3d/grain_mesh_3d.hpp"
#include "grains3d/surface_mesh.hpp"
#include "tessellate/tessellation_3d.hpp"
#include "tessellate/tessellate_3d.hpp"

using namespace grainmesh;

namespace {

struct Case {
  std::string name;
  int grains;
  double per_grain;      // tetrahedra wanted per grain
  double limit_seconds;  // the goal, 0 = none
};

Tessellation3Options cell_options(const Case& c) {
  Tessellation3Options o;
  o.width = o.height = o.depth = std::cbrt(static_cast<double>(c.grains)) * 0.5;  // grains of about 0.6 diameter
  o.grains = c.grains;
  o.lloyd_iterations = 5;
  o.phases = {Phase{"WC", 0.0, true, 700e9, 0.24, {}}, Phase{"Co", 0.15, false, 211e9, 0.31, {}}};
  return o;
}

Json quality_json(const TetMesh& m, double grains) {
  const TetQuality q = measure_quality(m);
  return {{"points", m.points.size()},
          {"cells", m.tets.size()},
          {"cells_per_grain_mean", static_cast<double>(m.tets.size()) / grains},
          {"q_min", q.q_min},
          {"q_mean", q.q_mean},
          {"min_dihedral_deg", q.min_dihedral_deg},
          {"share_dihedral_below_10", q.share_dihedral_below_10}};
}

// The same polyhedra as a Gmsh .geo: a point per vertex, a line per edge, a plane surface
// per face, a volume per region (its faces shared with its neighbours), meshed at edge h
// by Gmsh's 3D Delaunay with its optimiser.
void write_geo(const std::filesystem::path& file, const Tessellation3& t, double h) {
  std::ofstream out(file);
  out.precision(17);
  for (std::size_t v = 0; v < t.vertices.size(); ++v)
    out << "Point(" << v + 1 << ") = {" << t.vertices[v].x << ", " << t.vertices[v].y << ", " << t.vertices[v].z << ", " << h << "};\n";
  std::map<std::pair<int, int>, int> line;
  for (std::size_t f = 0; f < t.faces.size(); ++f) {
    const auto& ring = t.faces[f].ring;
    std::string loop;
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const int a = ring[k], b = ring[(k + 1) % ring.size()];
      const auto [it, added] = line.emplace(std::minmax(a, b), static_cast<int>(line.size()) + 1);
      if (added) out << "Line(" << it->second << ") = {" << std::min(a, b) + 1 << ", " << std::max(a, b) + 1 << "};\n";
      loop += (loop.empty() ? "" : ", ") + std::to_string(a < b ? it->second : -it->second);
    }
    out << "Curve Loop(" << f + 1 << ") = {" << loop << "};\nPlane Surface(" << f + 1 << ") = {" << f + 1 << "};\n";
  }
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    std::string loop;
    for (int f : t.regions[r].faces) loop += (loop.empty() ? "" : ", ") + std::to_string(f + 1);
    out << "Surface Loop(" << r + 1 << ") = {" << loop << "};\nVolume(" << r + 1 << ") = {" << r + 1 << "};\n";
  }
  out << "Mesh.CharacteristicLengthMax = " << h << ";\nMesh.Optimize = 1;\n";
}

// Our surface mesh as discrete Gmsh surfaces (a .msh, one elementary entity per face) and
// a .geo that merges it and makes a volume per region: Gmsh as the second filler, its
// volumes keeping our surface triangles as TetGen's do.
void write_surface_geo(const std::filesystem::path& dir, const Tessellation3& t, double h) {
  const SurfaceMesh s = mesh_surfaces(t, h);
  std::ofstream msh(dir / "surface.msh");
  msh.precision(17);
  msh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << s.points.size() << "\n";
  for (std::size_t v = 0; v < s.points.size(); ++v) msh << v + 1 << ' ' << s.points[v].x << ' ' << s.points[v].y << ' ' << s.points[v].z << '\n';
  std::size_t count = 0;
  for (const auto& f : s.faces) count += f.size();
  msh << "$EndNodes\n$Elements\n" << count << "\n";
  std::size_t id = 0;
  for (std::size_t f = 0; f < s.faces.size(); ++f)
    for (const auto& tr : s.faces[f])
      msh << ++id << " 2 2 " << f + 1 << ' ' << f + 1 << ' ' << tr[0] + 1 << ' ' << tr[1] + 1 << ' ' << tr[2] + 1 << '\n';
  msh << "$EndElements\n";
  std::ofstream geo(dir / "filler.geo");
  geo << "Merge \"surface.msh\";\n";
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    std::string loop;
    for (int f : t.regions[r].faces)  // a bent face's pieces: its triangles on some (surface_mesh.hpp)
      if (!s.faces[f].empty()) loop += (loop.empty() ? "" : ", ") + std::to_string(f + 1);
    geo << "Surface Loop(" << r + 1 << ") = {" << loop << "};\nVolume(" << r + 1 << ") = {" << r + 1 << "};\n";
  }
  geo << "Mesh.CharacteristicLengthMax = " << h << ";\nMesh.Optimize = 1;\nMesh.SaveAll = 1;\n";
}

// Gmsh run on `geo` (write_geo: meshing the polyhedra itself; write_surface_geo: filling
// our surfaces), timed as a program, its tetrahedra measured by our measures.
Json gmsh_peer(const Case& c, const std::filesystem::path& scratch, bool our_surfaces) {
  Tessellation3Options o = cell_options(c);
  Rng rng(1);
  const Tessellation3 t = tessellate_3d(o, rng);
  const double h = size_for_tets_per_grain(t, c.per_grain);
  const auto geo = scratch / (our_surfaces ? "filler.geo" : "cell.geo"), msh = scratch / "cell.msh";
  if (our_surfaces) write_surface_geo(scratch, t, h);
  else write_geo(geo, t, h);
  const ProcessRun r = run_process({"gmsh", geo.string(), "-3", "-nt", "2", "-format", "msh2", "-o", msh.string()},
                                   scratch / "gmsh.log");
  if (r.exit_code != 0) return {{"error", "gmsh failed (exit " + std::to_string(r.exit_code) + ")"}};
  Json j{{"seconds", r.seconds}, {"peak_memory_mib", r.peak_mib}};
  j.update(quality_json(read_msh2_tets(msh), static_cast<double>(t.grains.size())));
  return j;
}

Json measure(const Case& c) {
  Tessellation3Options o = cell_options(c);
  Rng rng(1);
  const auto start = std::chrono::steady_clock::now();
  const Tessellation3 t = tessellate_3d(o, rng);
  const double tessellate_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const GrainMesh3 m = mesh_tessellation_3d(t, {.size = size_for_tets_per_grain(t, c.per_grain)});
  check_conformity(t, m);
  // The same measures over the tetrahedra with a point on a surface, and the rest.
  TetMesh surface, inner;
  surface.points = inner.points = m.mesh.points;
  for (const auto& tet : m.mesh.tets) {
    bool touches = false;
    for (int p : tet) touches = touches || p < m.surface_points;
    (touches ? surface : inner).tets.push_back(tet);
  }
  const TetQuality qs = measure_quality(surface), qi = measure_quality(inner);
  Json j{{"seconds", tessellate_seconds + m.seconds},
         {"tessellate_seconds", tessellate_seconds},
         {"surface_seconds", m.surface_seconds},
         {"fill_seconds", m.fill_seconds},
         {"grains", t.grains.size()}};
  j.update(quality_json(m.mesh, static_cast<double>(t.grains.size())));
  j.update(Json{{"surface_tets_q_mean", qs.q_mean},
          {"surface_tets_min_dihedral_deg", qs.min_dihedral_deg},
          {"inner_tets_q_mean", qi.q_mean},
          {"inner_tets_min_dihedral_deg", qi.min_dihedral_deg},
          {"tessellation_sharpest_dihedral_deg", t.stats.sharpest_dihedral_deg}});
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path source = argc > 1 ? argv[1] : ".";
  const std::filesystem::path scratch = std::filesystem::temp_directory_path() / ("grainmesh-bench-mesh3d-" + std::to_string(getpid()));
  std::filesystem::create_directories(scratch);
  const std::vector<Case> cases{
      {"100 grains, 500 tets/grain", 100, 500, 0},
      {"1000 grains, 500 tets/grain", 1000, 500, 60},
  };
  Json results = Json::array();
  std::printf("%-30s %8s %8s %8s %9s %8s %7s %8s %8s %9s\n", "case", "tess s", "surf s", "fill s", "cells", "q_mean",
              "q_min", "min dih", "<10 deg", "peak MiB");
  std::fflush(stdout);
  for (const Case& c : cases) {
    Json row = median_in_children(1, [&] { return measure(c); });
    if (row.contains("error")) {
      std::printf("%-30s error: %s\n", c.name.c_str(), row["error"].get<std::string>().c_str());
      return 1;
    }
    std::printf("%-30s %8.2f %8.2f %8.2f %9zu %8.3f %7.3f %8.2f %8.4f %9.1f\n", c.name.c_str(),
                row["tessellate_seconds"].get<double>(), row["surface_seconds"].get<double>(),
                row["fill_seconds"].get<double>(), row["cells"].get<std::size_t>(), row["q_mean"].get<double>(),
                row["q_min"].get<double>(), row["min_dihedral_deg"].get<double>(),
                row["share_dihedral_below_10"].get<double>(), row["peak_memory_mib"].get<double>());
    std::printf("%-30s surface tets q_mean %.3f min dihedral %.2f; inner q_mean %.3f min dihedral %.2f\n", "",
                row["surface_tets_q_mean"].get<double>(), row["surface_tets_min_dihedral_deg"].get<double>(),
                row["inner_tets_q_mean"].get<double>(), row["inner_tets_min_dihedral_deg"].get<double>());
    std::fflush(stdout);
    const bool have_gmsh = !gmsh_version(scratch).empty();
    Json peers;
    for (const bool ours : {false, true}) {
      const char* name = ours ? "gmsh_filler" : "gmsh";
      peers[name] = have_gmsh ? gmsh_peer(c, scratch, ours) : Json{{"error", "gmsh is not installed (make bench installs it)"}};
      const Json& g = peers[name];
      const char* label = ours ? "Gmsh filling our surfaces" : "Gmsh (.geo, same polyhedra)";
      if (g.contains("error")) {
        std::printf("%-30s %s: %s\n", "", label, g["error"].get<std::string>().c_str());
        continue;
      }
      std::printf("%-30s %s: %.2f s, %zu cells, q_mean %.3f, q_min %.3f, min dihedral %.2f, <10 deg %.4f, %.1f MiB\n", "",
                  label, g["seconds"].get<double>(), g["cells"].get<std::size_t>(), g["q_mean"].get<double>(),
                  g["q_min"].get<double>(), g["min_dihedral_deg"].get<double>(), g["share_dihedral_below_10"].get<double>(),
                  g["peak_memory_mib"].get<double>());
      std::fflush(stdout);
    }
    std::fflush(stdout);
    Json labelled{{"case", c.name}};
    labelled.update(row);
    labelled.update(peers);
    if (c.limit_seconds > 0) labelled["limit_seconds"] = c.limit_seconds;
    results.push_back(labelled);
  }
  std::filesystem::remove_all(scratch);
  write_results(source / "bench" / "results.json", "mesh3d",
                "one run each in a fresh process; TetGen on all cores", results);
  return 0;
}
