#include "grains3d/grain_mesh_3d.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/process.hpp"
#include "grains3d/improve_tets.hpp"
#include "grains3d/surface_mesh.hpp"

namespace grainmesh {

namespace {

// A region's tetrahedra before assembly: ids >= 0 are surface points, < 0 are -(1 + k)
// for the region's own interior point k.
struct RegionTets {
  std::vector<Vec3> interior;
  std::vector<std::array<int, 4>> tets;
};

// A scratch directory for TetGen's files, removed with it.
class ScratchDirectory {
 public:
  ScratchDirectory() {
    std::string pattern = (std::filesystem::temp_directory_path() / "grainmesh-tetgen-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw IoError("cannot create a scratch directory for TetGen in " + pattern);
    path_ = pattern;
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The lines of a TetGen output file without comments.
std::vector<std::vector<double>> read_table(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw GeometryError("TetGen wrote no " + file.filename().string());
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::vector<double> row;
    for (double v; words >> v;) row.push_back(v);
    if (!row.empty()) rows.push_back(std::move(row));
  }
  return rows;
}

// Fills region r: its surface triangles (outward) written as a TetGen .smesh, TetGen told
// to keep them (-Y), its output read back.
RegionTets fill_region(const Tessellation3& t, int r, const std::vector<Vec3>& points,
                       const std::vector<std::vector<std::array<int, 3>>>& faces, const GrainMesh3Options& o,
                       const std::filesystem::path& dir) {
  std::map<int, int> local;
  std::vector<int> global;
  std::vector<std::array<int, 3>> tris;
  for (int f : t.regions[r].faces)
    for (auto tr : faces[f]) {
      if (t.faces[f].back != r) std::swap(tr[1], tr[2]);
      for (int& v : tr) {
        const auto [it, added] = local.emplace(v, static_cast<int>(global.size()));
        if (added) global.push_back(v);
        v = it->second;
      }
      tris.push_back(tr);
    }
  std::string name = std::to_string(r);  // not "r" + ...: GCC 12's -Wrestrict misfires on that
  name.insert(0, 1, 'r');
  {
    std::ofstream out(dir / (name + ".smesh"));
    char buf[128];
    out << global.size() << " 3 0 0\n";
    for (std::size_t k = 0; k < global.size(); ++k) {
      const Vec3 p = points[global[k]];
      std::snprintf(buf, sizeof buf, "%zu %.17g %.17g %.17g\n", k, p.x, p.y, p.z);
      out << buf;
    }
    out << tris.size() << " 0\n";
    for (const auto& tr : tris) out << "3 " << tr[0] << ' ' << tr[1] << ' ' << tr[2] << '\n';
    out << "0\n0\n";
    if (!out) throw IoError((dir / (name + ".smesh")).string() + ": cannot write TetGen's input");
  }
  // TetGen 1.5.0 trips an assertion in its point location on a few inputs (a small region
  // with a face on the box, say); another point insertion order (its -b switch) gets
  // past it, and the first order that works is used, so the result stays deterministic.
  const double max_volume = regular_tet_volume(o.size);
  int code = 0;
  for (const char* order : {"", "b/1", "b/0.5"}) {
    char switches[128];
    std::snprintf(switches, sizeof switches, "-pYzQq%.6g/%.6ga%.6gO7/7%s", o.radius_edge, o.min_dihedral_deg, max_volume, order);
    code = run_child({"tetgen", switches, name + ".smesh"}, dir, dir / (name + ".log"), o.deadline,
                     "TetGen filling region " + std::to_string(r));
    if (code == 127) throw GeometryError("TetGen (the tetgen program) is not installed: make run installs it");
    if (code == 0) break;
  }
  if (code != 0) throw GeometryError("TetGen failed on region " + std::to_string(r) + " (exit code " + std::to_string(code) + ")");
  const auto nodes = read_table(dir / (name + ".1.node"));
  const auto eles = read_table(dir / (name + ".1.ele"));
  if (nodes.empty() || eles.empty() || nodes.size() - 1 < global.size())
    throw GeometryError("TetGen's output for region " + std::to_string(r) + " is incomplete");
  // The region's points and tetrahedra in TetGen's numbering (its first points are the
  // surface's, in the order given), positive; the inner points smoothed.
  const int nb = static_cast<int>(global.size());
  std::vector<Vec3> local_points;
  for (int k = 0; k < nb; ++k) local_points.push_back(points[global[k]]);
  for (std::size_t k = 1 + global.size(); k < nodes.size(); ++k) local_points.push_back({nodes[k][1], nodes[k][2], nodes[k][3]});
  std::vector<std::array<int, 4>> local_tets;
  for (std::size_t k = 1; k < eles.size(); ++k) {
    std::array<int, 4> tet{};
    for (int c = 0; c < 4; ++c) tet[c] = static_cast<int>(eles[k][1 + c]);
    const auto& p = local_points;
    if (tet_volume(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]) < 0.0) std::swap(tet[2], tet[3]);
    local_tets.push_back(tet);
  }
  improve_tets(local_points, local_tets, nb, o.improvement_passes);
  RegionTets out;
  out.interior.assign(local_points.begin() + nb, local_points.end());
  for (const auto& tet : local_tets) {
    std::array<int, 4> mapped{};
    for (int c = 0; c < 4; ++c) mapped[c] = tet[c] < nb ? global[tet[c]] : -1 - (tet[c] - nb);
    out.tets.push_back(mapped);
  }
  std::error_code ignored;
  for (const char* ext : {".smesh", ".1.node", ".1.ele", ".1.face", ".1.edge", ".log"})
    std::filesystem::remove(dir / (name + ext), ignored);
  return out;
}

}  // namespace

double size_for_tets_per_grain(const Tessellation3& t, double per_grain) {
  constexpr double kTetsPerBound = 1.3;
  const double grain = t.width * t.height * t.depth / static_cast<double>(std::max<std::size_t>(1, t.grains.size()));
  return regular_tet_edge(kTetsPerBound * grain / per_grain);
}

GrainMesh3 mesh_tessellation_3d(const Tessellation3& t, const GrainMesh3Options& o) {
  if (!(o.size > 0.0)) throw GeometryError("3D mesh: the element size must be positive");
  const auto start = std::chrono::steady_clock::now();
  auto since = [](auto from) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count(); };
  SurfaceMesh surface = mesh_surfaces(t, o.size);
  GrainMesh3 m;
  m.surface_seconds = since(start);
  m.surface_points = static_cast<int>(surface.points.size());
  for (const auto& f : surface.faces) m.surface_triangles += static_cast<int>(f.size());

  const auto fill_start = std::chrono::steady_clock::now();
  const int nr = static_cast<int>(t.regions.size());
  std::vector<RegionTets> pieces(nr);
  ScratchDirectory dir;
  tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(0, nr, [&](int r) { pieces[r] = fill_region(t, r, surface.points, surface.faces, o, dir.path()); });
  });
  m.fill_seconds = since(fill_start);

  m.mesh.points = std::move(surface.points);
  m.pairs = std::move(surface.pairs);
  m.faces = std::move(surface.faces);
  for (int r = 0; r < nr; ++r) {
    const int first = static_cast<int>(m.mesh.points.size());
    m.mesh.points.insert(m.mesh.points.end(), pieces[r].interior.begin(), pieces[r].interior.end());
    for (auto tet : pieces[r].tets) {
      for (int& v : tet)
        if (v < 0) v = first + (-1 - v);
      const auto& p = m.mesh.points;
      if (tet_volume(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]) < 0.0) std::swap(tet[2], tet[3]);
      m.mesh.tets.push_back(tet);
      m.grain.push_back(t.regions[r].grain);
      m.phase.push_back(t.regions[r].phase);
      m.region.push_back(r);
    }
  }
  m.seconds = since(start);
  return m;
}

}  // namespace grainmesh
