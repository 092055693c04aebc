// make bench: the finite-element reference (homogenise.reference = fe) — its time and the
// OpenFOAM answer's error against it. `grainmesh run --solve` with the reference, periodic,
// on the default 2D cell (100 grains), a 1,000-grain 2D cell of the same grain size, and
// the 3D WC-Co example (100 grains): the reference's unknowns and seconds (from the
// report), and the answer's largest relative error on the stiffness's diagonal and off
// it (the entries of their own scale), K and G. One run each (a fresh process).
// The reference checked by someone else's code: on the default 2D cell and on a 12-grain 3D
// cell, SfePy (bench/sfepy_reference.py, Debian python3-sfepy) homogenises the same mesh
// with the same quadratic elements; the largest difference of their stiffnesses, relative
// to the largest entry, must be solver precision (under 1e-6).
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
  std::printf("%-30s %9s %10s %10s %10s %8s %8s %12s\n", "cell", "unknowns", "reference s", "diagonal", "off diag.",
              "K", "G", "SfePy diff.");
  bool peers_agree = true;
  for (const Cell& c : cells) {
    const fs::path out = dir / "run";
    fs::remove_all(out);
    run_command(GRAINMESH_BINARY,
                "run " + c.config + " -o " + out.string() +
                    " --solve --quiet --set homogenise.boundary=periodic --set homogenise.reference=fe "
                    "--set output.pictures=none",
                dir / "run.log");
    const Json eff = read_json(out / "report.json")["effective"];
    const Json& ref = eff["reference"];
    const Json& error = eff["discretisation_error"];
    // The largest error of the diagonal entries, and of the others of their own scale.
    double diagonal = 0.0, off = 0.0, largest = 0.0;
    for (const auto& [name, value] : ref["stiffness"].items()) largest = std::max(largest, std::abs(value.get<double>()));
    for (const auto& [name, value] : error["stiffness"].items()) {
      const bool on_diagonal = name[1] == name[2];
      if (!on_diagonal && std::abs(ref["stiffness"][name].get<double>()) < 0.01 * largest) continue;
      double& most = on_diagonal ? diagonal : off;
      most = std::max(most, std::abs(value.get<double>()));
    }
    Json row{{"cell", c.name},
             {"unknowns", ref["unknowns"]},
             {"reference_seconds", ref["seconds"]},
             {"largest_diagonal_error", diagonal},
             {"largest_off_diagonal_error", off},
             {"bulk_modulus_error", error["bulk_modulus"]},
             {"shear_modulus_error", error["shear_modulus"]}};
    std::string peer = "-";
    if (c.peer) {
      const double difference = sfepy_difference(source, out, ref["stiffness"], dir);
      row["sfepy_largest_relative_difference"] = difference;
      peers_agree = peers_agree && difference < 1e-6;
      char text[32];
      std::snprintf(text, sizeof text, "%.1e", difference);
      peer = text;
    }
    std::printf("%-30s %9d %10.2f %9.2f%% %9.2f%% %+7.2f%% %+7.2f%% %12s\n", c.name, ref["unknowns"].get<int>(),
                ref["seconds"].get<double>(), 100 * diagonal, 100 * off, 100 * error["bulk_modulus"].get<double>(),
                100 * error["shear_modulus"].get<double>(), peer.c_str());
    std::fflush(stdout);
    results.push_back(row);
  }
  fs::remove_all(dir);
  write_results(source / "bench" / "results.json", "reference",
                "one run of grainmesh run --solve with homogenise.reference = fe (periodic, no pictures) per row; the "
                "reference's unknowns and seconds and the OpenFOAM answer's errors against it from the report",
                results);
  if (!peers_agree) std::fprintf(stderr, "bench_reference: SfePy and the reference differ by more than 1e-6\n");
  return peers_agree ? 0 : 1;
}
