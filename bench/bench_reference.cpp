// make bench: the finite elements (homogenise.solver = fe, the default on periodic cells)
// — their time, their own error estimate and the OpenFOAM answer's error against them.
// `grainmesh run --solve`, periodic, on the default 2D cell (100 grains), a 1,000-grain 2D
// cell of the same grain size, and the 3D WC-Co example (100 grains): the finite
// elements' unknowns and seconds (both levels, from the report), the largest of their
// error estimates, and OpenFOAM's largest relative error on the stiffness's diagonal and
// off it (the entries of their own scale), K and G (effective.openfoam). One run each (a
// fresh process).
// The finite elements checked by someone else's code: on the default 2D cell and on a
// 12-grain 3D cell, SfePy (bench/sfepy_reference.py, Debian python3-sfepy) homogenises the
// same mesh (fe_mesh.vtu) with the same quadratic elements; the largest difference of
// their stiffnesses, relative to the largest entry, must be solver precision (under 1e-6).
// Writes bench/results.json ("reference").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "bench/child.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

namespace {

// SfePy's stiffness on the mesh of run `out` against the reference's `stiffness`: the
// largest difference of an entry, relative to the largest entry.
double sfepy_difference(const fs::path& source, const fs::path& out, const Json& stiffness, const fs::path& dir) {
  const fs::path answer = dir / "sfepy.json";
  run_command("/usr/bin/python3", (source / "bench" / "sfepy_reference.py").string() + " " + out.string() + " " +
                                      answer.string(), dir / "sfepy.log");
  const Json peer = read_json(answer)["stiffness"];
  double largest = 0.0, difference = 0.0;
  for (const auto& [name, value] : stiffness.items()) {
    largest = std::max(largest, std::abs(value.get<double>()));
    difference = std::max(difference, std::abs(value.get<double>() - peer.at(name).get<double>()));
  }
  return difference / largest;
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const fs::path dir = fs::temp_directory_path() / "grainmesh-bench-reference";
  fs::remove_all(dir);
  fs::create_directories(dir);
  struct Cell {
    const char* name;
    std::string config;  // the config file and its --set's
    bool peer = false;   // SfePy homogenises its mesh too
  };
  const fs::path small = dir / "cell_3d_12.ini";
  std::ofstream(small) << "[domain]\nwidth = 1\nheight = 1\ndepth = 1\nperiodic = true\n"
                          "[tessellation]\ngrains = 12\nseed = 5\nlloyd_iterations = 3\n"
                          "[phase.WC]\nfraction = rest\nE = 700e9\nnu = 0.2\n"
                          "[phase.Co]\nfraction = 0.2\nE = 210e9\nnu = 0.3\n[mesh]\ntets_per_grain = 150\n";
  const std::string three = (source / "data" / "examples" / "grains_3d_wc_co.ini").string();
  // The default cell is 1 x 1 with 100 grains: 1,000 of the same size fill sqrt(10) a side.
  const Cell cells[] = {{"2D default, 100 grains", "", true},
                        {"2D default, 1,000 grains",
                         "--set tessellation.grains=1000 --set domain.width=3.1623 --set domain.height=3.1623"},
                        {"3D WC-Co example, 100 grains", three},
                        {"3D, 12 grains", small.string(), true}};
  Json results = Json::array();
  std::printf("%-30s %9s %8s %9s | OpenFOAM: %9s %9s %8s %8s | %11s\n", "cell", "unknowns", "fe s", "estimate",
              "diagonal", "off diag.", "K", "G", "SfePy diff.");
  bool peers_agree = true;
  for (const Cell& c : cells) {
    const fs::path out = dir / "run";
    fs::remove_all(out);
    run_command(GRAINMESH_BINARY,
                "run " + c.config + " -o " + out.string() +
                    " --solve --quiet --set homogenise.boundary=periodic --set output.pictures=basic",
                dir / "run.log");
    const Json eff = read_json(out / "report.json")["effective"];
    const Json& fe = eff["finite_elements"];
    const Json& error = eff["openfoam"]["discretisation_error"];
    // The largest error of the diagonal entries, and of the others of their own scale.
    double diagonal = 0.0, off = 0.0, largest = 0.0, estimate = 0.0;
    for (const auto& [name, value] : eff["stiffness"].items()) largest = std::max(largest, std::abs(value.get<double>()));
    for (const auto& [name, value] : error["stiffness"].items()) {
      const bool on_diagonal = name[1] == name[2];
      if (!on_diagonal && std::abs(eff["stiffness"][name].get<double>()) < 0.01 * largest) continue;
      double& most = on_diagonal ? diagonal : off;
      most = std::max(most, std::abs(value.get<double>()));
      estimate = std::max(estimate, eff["error_estimate"]["stiffness"][name].get<double>());
    }
    Json row{{"cell", c.name},
             {"unknowns", fe["unknowns"]},
             {"fe_seconds", fe["seconds"]},
             {"largest_error_estimate", estimate},
             {"openfoam_largest_diagonal_error", diagonal},
             {"openfoam_largest_off_diagonal_error", off},
             {"openfoam_bulk_modulus_error", error["bulk_modulus"]},
             {"openfoam_shear_modulus_error", error["shear_modulus"]}};
    std::string peer = "-";
    if (c.peer) {
      const double difference = sfepy_difference(source, out, eff["stiffness"], dir);
      row["sfepy_largest_relative_difference"] = difference;
      peers_agree = peers_agree && difference < 1e-6;
      char text[32];
      std::snprintf(text, sizeof text, "%.1e", difference);
      peer = text;
    }
    std::printf("%-30s %9d %8.2f %8.3f%% | OpenFOAM: %8.2f%% %8.2f%% %+7.2f%% %+7.2f%% | %11s\n", c.name,
                fe["unknowns"].get<int>(), fe["seconds"].get<double>(), 100 * estimate, 100 * diagonal, 100 * off,
                100 * error["bulk_modulus"].get<double>(), 100 * error["shear_modulus"].get<double>(), peer.c_str());
    std::fflush(stdout);
    results.push_back(row);
  }
  fs::remove_all(dir);
  write_results(source / "bench" / "results.json", "reference",
                "one run of grainmesh run --solve (periodic, homogenise.solver = fe, basic pictures) per row; the finite "
                "elements' unknowns and seconds (both levels), their largest error estimate and OpenFOAM's errors "
                "against them from the report",
                results);
  if (!peers_agree) std::fprintf(stderr, "bench_reference: SfePy and grainmesh's finite elements differ by more than 1e-6\n");
  return peers_agree ? 0 : 1;
}
