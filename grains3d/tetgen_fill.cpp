#include "grains3d/tetgen_fill.hpp"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/process.hpp"
#include "mesh/tetmesh.hpp"

namespace grainmesh {

namespace {

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

std::string smesh_text(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles) {
  std::string text = std::to_string(points.size()) + " 3 0 0\n";
  char buf[128];
  for (std::size_t k = 0; k < points.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%zu %.17g %.17g %.17g\n", k, points[k].x, points[k].y, points[k].z);
    text += buf;
  }
  text += std::to_string(triangles.size()) + " 0\n";
  for (const auto& t : triangles)
    text += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  return text + "0\n0\n";
}

// The enclosed volume of a closed surface turning outward (divergence theorem).
double enclosed_volume(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles) {
  double six_v = 0.0;
  for (const auto& t : triangles) six_v += dot(points[t[0]], cross(points[t[1]], points[t[2]]));
  return six_v / 6.0;
}

// Keeps `text` as a file of its own in the system's temporary directory; its path.
std::filesystem::path keep(const std::string& text, const std::string& name) {
  std::string pattern = (std::filesystem::temp_directory_path() / ("grainmesh-" + name + "-XXXXXX.smesh")).string();
  const int fd = mkstemps(pattern.data(), 6);
  if (fd < 0) return {};
  const bool written = write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  close(fd);
  return written ? std::filesystem::path(pattern) : std::filesystem::path();
}

}  // namespace

ScratchDirectory::ScratchDirectory() {
  // Named here, registered before it exists, then made: an interrupt at any moment finds it
  // registered (mkdtemp would make it before its name could be registered).
  static std::atomic<int> next{0};
  const std::filesystem::path tmp = std::filesystem::temp_directory_path();
  for (int attempt = 0; attempt < 100; ++attempt) {
    path_ = tmp / ("grainmesh-tetgen-" + std::to_string(getpid()) + "-" + std::to_string(next++));
    registered_ = TemporaryPath(path_);
    std::error_code ec;
    if (std::filesystem::create_directory(path_, ec)) return;
    if (ec) break;
  }
  registered_.release();
  throw IoError("cannot create a scratch directory for TetGen in " + tmp.string());
}

ScratchDirectory::~ScratchDirectory() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

double tetgen_budget(const TetgenOptions& o, double volume) {
  constexpr double kTetsPerBound = 1.3;  // TetGen makes about 1.3 tetrahedra per volume bound (grain_mesh_3d.hpp)
  return o.budget_seconds + o.budget_seconds_per_tet * kTetsPerBound * std::max(0.0, volume) / o.max_volume;
}

TetgenFill tetgen_fill(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                       const TetgenOptions& o, const std::filesystem::path& dir, const std::string& name,
                       const std::string& what) {
  const std::string input = smesh_text(points, triangles);
  {
    std::ofstream out(dir / (name + ".smesh"));
    out << input;
    if (!out) throw IoError((dir / (name + ".smesh")).string() + ": cannot write TetGen's input");
  }
  const double budget = tetgen_budget(o, enclosed_volume(points, triangles));
  TetgenFill fill;
  std::string tried;
  int code = 0;
  for (const char* order : kTetgenOrders) {
    char switches[128];
    std::snprintf(switches, sizeof switches, "-pYzQq%.6g/%.6ga%.6gO7/7%s", o.radius_edge, o.min_dihedral_deg,
                  o.max_volume, order);
    ++fill.tries;
    code = run_child({"tetgen", switches, name + ".smesh"}, dir, dir / (name + ".log"), o.deadline, "TetGen filling " + what,
                     {}, {}, {.seconds = budget});
    if (code == 127) throw GeometryError("TetGen (the tetgen program) is not installed: make run installs it");
    if (code == 0) {
      fill.switches = switches;
      break;
    }
    tried += (tried.empty() ? "" : ", ") + std::string(switches) +
             (code == kChildOverBudget ? " did not finish in " + to_text(budget, 3) + " s"
                                       : " failed (exit code " + std::to_string(code) + ")");
  }
  if (code != 0) {
    const std::filesystem::path kept = keep(input, name);
    throw GeometryError("TetGen could not fill " + what + ": " + tried + "; its input is kept as " +
                        (kept.empty() ? std::string("(it could not be kept)") : kept.string()) +
                        " (report it); a slightly different mesh size (mesh.tets_per_grain) or seed gives other surfaces");
  }
  const auto nodes = read_table(dir / (name + ".1.node"));
  const auto eles = read_table(dir / (name + ".1.ele"));
  if (nodes.empty() || eles.empty() || nodes.size() - 1 < points.size())
    throw GeometryError("TetGen's output for " + what + " is incomplete");
  // TetGen's numbering: its first points are the surface's, in the order given.
  fill.points = points;
  for (std::size_t k = 1 + points.size(); k < nodes.size(); ++k) fill.points.push_back({nodes[k][1], nodes[k][2], nodes[k][3]});
  for (std::size_t k = 1; k < eles.size(); ++k) {
    std::array<int, 4> tet{};
    for (int c = 0; c < 4; ++c) tet[c] = static_cast<int>(eles[k][1 + c]);
    const auto& p = fill.points;
    if (tet_volume(p[tet[0]], p[tet[1]], p[tet[2]], p[tet[3]]) < 0.0) std::swap(tet[2], tet[3]);
    fill.tets.push_back(tet);
  }
  std::error_code ignored;
  for (const char* ext : {".smesh", ".1.node", ".1.ele", ".1.face", ".1.edge", ".log"})
    std::filesystem::remove(dir / (name + ext), ignored);
  return fill;
}

}  // namespace grainmesh
