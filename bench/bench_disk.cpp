// make bench: the unit disk at a target edge length of 0.004 (about 450k triangles),
// meshed by grainmesh and by its peers on the same machine in the same run: Gmsh's
// Frontal-Delaunay and Delaunay (one thread), and CGAL's Delaunay_mesher_2 with Lloyd.
// Each is a whole program run in a child process, three times in turn (median); each writes its
// mesh, which is read back and measured with grainmesh's own quality measures.
// Two times per row: "mesher s", the program's own timer around its meshing alone
// (grainmesh: report.json "seconds"; Gmsh: its log's "Done meshing 2D (Wall ..)"; CGAL:
// refinement + Lloyd), and "process s", the whole run including reading the input and
// writing the mesh (grainmesh also writes mesh.png and a report). Prints a table and
// updates bench/results.json ("disk").
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "bench/peers.hpp"
#include "pipelines/output_dir.hpp"
#include "view/vtu.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

constexpr double kSize = 0.004;

struct Peer {
  std::string name;
  std::function<std::vector<std::string>(const fs::path& dir)> command;  // run in dir
  std::function<double(const fs::path& dir, const ProcessRun& run)> mesher_seconds;
  std::function<TriMesh(const fs::path& dir)> mesh;
};

// One run of `peer` in a fresh directory: its times, its mesh's measures, its memory.
Json run_once(const Peer& peer, const fs::path& dir) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  const ProcessRun r = run_process(peer.command(dir), dir / "log.txt");
  if (r.exit_code != 0) return {{"error", "exit code " + std::to_string(r.exit_code) + ": " + r.output.substr(0, 400)}};
  Json row{{"seconds", peer.mesher_seconds(dir, r)}, {"process_seconds", r.seconds}};
  row.update(mesh_measures(peer.mesh(dir)));
  row["peak_memory_mib"] = r.peak_mib;
  fs::remove_all(dir);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const int runs = 3;
  const fs::path scratch = fs::temp_directory_path() / "grainmesh-bench-disk";
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  const std::string gmsh = gmsh_version(scratch);
  if (gmsh.empty()) {
    std::fprintf(stderr, "bench_disk: gmsh is not installed (make bench installs it: scripts/install-deps.sh --bench)\n");
    return 1;
  }
  const fs::path geo = scratch / "disk.geo";
  std::ofstream(geo) << "// The unit disk, every edge about " << kSize << " long.\n"
                     << "SetFactory(\"OpenCASCADE\");\nDisk(1) = {0, 0, 0, 1};\n"
                     << "Mesh.MeshSizeMin = " << kSize << ";\nMesh.MeshSizeMax = " << kSize << ";\n"
                     << "Mesh.MeshSizeFromCurvature = 0;\n";

  auto gmsh_peer = [&](const std::string& name, const std::string& algo) {
    return Peer{name,
                [=](const fs::path& dir) {
                  return std::vector<std::string>{"gmsh", geo.string(), "-2", "-algo", algo, "-nt", "1", "-format",
                                                  "msh22", "-o", (dir / "mesh.msh").string()};
                },
                [](const fs::path&, const ProcessRun& r) { return gmsh_meshing_seconds(r.output); },
                [](const fs::path& dir) { return read_msh2(dir / "mesh.msh"); }};
  };
  const std::vector<Peer> peers{
      {"grainmesh",
       [&](const fs::path& dir) {
         return std::vector<std::string>{GRAINMESH_BINARY, "domain", (source / "bench/cases/disk_h0004.ini").string(),
                                         "-o", (dir / "out").string()};
       },
       [](const fs::path& dir, const ProcessRun&) {
         return Json::parse(read_text_file(dir / "out" / "report.json"))["seconds"].get<double>();
       },
       [](const fs::path& dir) { return *as_triangles(read_vtu(dir / "out" / "mesh.vtu").mesh); }},
      gmsh_peer("Gmsh Frontal-Delaunay", "front2d"),
      gmsh_peer("Gmsh Delaunay", "del2d"),
      // A refinement mesher's edges are at most its bound: 1.5 h gives about our count.
      {"CGAL Delaunay_mesher_2 + Lloyd",
       [&](const fs::path& dir) {
         return std::vector<std::string>{CGAL_DISK_BINARY, std::to_string(kSize), std::to_string(1.5 * kSize), "10",
                                         "60", (dir / "mesh.msh").string()};
       },
       [](const fs::path&, const ProcessRun& r) {
         return Json::parse(r.output.substr(r.output.rfind('{')))["seconds"].get<double>();
       },
       [](const fs::path& dir) { return read_msh2(dir / "mesh.msh"); }},
  };

  std::printf("unit disk, h = %g (%s; CGAL %s)\n", kSize, gmsh.c_str(), GM_CGAL_VERSION);
  std::printf("%-32s %9s %9s %8s %9s %7s %7s %8s %8s %9s\n", "mesher", "mesher s", "process s", "x ours", "triangles",
              "q_min", "q_mean", "q<0.5", "min ang", "peak MiB");
  // Round after round, every mesher once per round, so that a slow spell of the
  // machine falls on all of them alike.
  std::vector<std::vector<Json>> samples(peers.size());
  for (int round = 0; round < runs; ++round)
    for (std::size_t k = 0; k < peers.size(); ++k) {
      Json row = run_once(peers[k], scratch / "run");
      if (row.contains("error")) {
        std::printf("%-32s error: %s\n", peers[k].name.c_str(), row["error"].get<std::string>().c_str());
        return 1;
      }
      samples[k].push_back(row);
    }
  Json results = Json::array();
  double ours = 0.0, ours_process = 0.0;
  for (std::size_t k = 0; k < peers.size(); ++k) {
    Json row = median_of(samples[k]);
    if (k == 0) ours = row["seconds"].get<double>(), ours_process = row["process_seconds"].get<double>();
    row["times_grainmesh_seconds"] = row["seconds"].get<double>() / ours;
    row["times_grainmesh_process_seconds"] = row["process_seconds"].get<double>() / ours_process;
    std::printf("%-32s %9.2f %9.2f %8.2f %9zu %7.3f %7.4f %8.4f %8.1f %9.1f\n", peers[k].name.c_str(),
                row["seconds"].get<double>(), row["process_seconds"].get<double>(),
                row["times_grainmesh_seconds"].get<double>(), row["triangles"].get<std::size_t>(),
                row["q_min"].get<double>(), row["q_mean"].get<double>(), row["q_below_0_5"].get<double>(),
                row["min_angle_deg"].get<double>(), row["peak_memory_mib"].get<double>());
    Json labelled{{"case", "unit disk h = 0.004"}, {"mesher", peers[k].name}};
    labelled.update(row);
    results.push_back(labelled);
  }
  fs::remove_all(scratch);
  write_results(source / "bench" / "results.json", "disk",
                "median of 3 runs, each a fresh process; seconds = the mesher's own timer around meshing alone, "
                "process_seconds = the whole program incl. reading input and writing the mesh; x ours = seconds / "
                "grainmesh's; " + gmsh + ", CGAL " + GM_CGAL_VERSION,
                results);
  return 0;
}
