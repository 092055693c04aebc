// make bench: a label image to a mesh. A 1,000-grain periodic tessellation drawn as a
// 2,000 x 2,000 16-bit PNG (grain g labelled g + 1), then `grainmesh run` on it (read,
// trace, simplify, mesh, write the case; no solve), median of three fresh processes, wall
// clock end to end; the bound is 10 s. Writes bench/results.json ("image").
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "bench/child.hpp"
#include "tessellate/label_image.hpp"
#include "tessellate/tessellate.hpp"

using namespace grainmesh;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  const fs::path source = argc > 1 ? argv[1] : ".";
  const fs::path dir = fs::temp_directory_path() / "grainmesh-bench-image";
  fs::remove_all(dir);
  fs::create_directories(dir);
  TessellationOptions o;
  o.grains = 1000;
  o.lloyd_iterations = 3;
  o.phases = {Phase{"WC", 0.0, true, 700e9, 0.24, {}}, Phase{"Co", 0.15, false, 211e9, 0.31, {}}};
  Rng rng(1);
  write_label_image(dir / "grains.png", draw_label_image(tessellate(o, rng), 2000));
  std::ofstream(dir / "image.ini") << "[domain]\nperiodic = true\n[tessellation]\nimage = "
                                   << (dir / "grains.png").string()
                                   << "\nimage_pixel_size = 0.0005\nimage_small_grains = merge\n"
                                      "[phase.WC]\nfraction = rest\nE = 700e9\nnu = 0.24\n"
                                      "[phase.Co]\nfraction = 0.15\nE = 211e9\nnu = 0.31\n[output]\npictures = none\n";
  constexpr double kLimit = 10.0;
  std::vector<Json> samples;
  for (int run = 0; run < 3; ++run) {
    const fs::path out = dir / "run";
    fs::remove_all(out);
    const auto start = std::chrono::steady_clock::now();
    run_command(GRAINMESH_BINARY, "run " + (dir / "image.ini").string() + " -o " + out.string() + " --quiet",
                dir / "run.log");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Json report = read_json(out / "report.json");
    samples.push_back({{"case", "1,000 grains, 2,000^2 pixels, periodic"},
                       {"seconds", seconds},
                       {"limit_seconds", kLimit},
                       {"grains", report["grains"]},
                       {"cells", report["mesh"]["cells"]},
                       {"stages", report["seconds"]}});
  }
  std::sort(samples.begin(), samples.end(),
            [](const Json& a, const Json& b) { return a["seconds"].get<double>() < b["seconds"].get<double>(); });
  const Json& row = samples[1];
  std::printf("%-40s %9.2f s (limit %.0f s) %s grains, %s cells\n", row["case"].get<std::string>().c_str(),
              row["seconds"].get<double>(), kLimit, row["grains"].dump().c_str(), row["cells"].dump().c_str());
  fs::remove_all(dir);
  write_results(source / "bench" / "results.json", "image",
                "median of 3 runs of grainmesh run (no solve) on a drawn label image, each a fresh process, wall clock",
                Json::array({row}));
  return row["seconds"].get<double>() < kLimit ? 0 : 1;
}
