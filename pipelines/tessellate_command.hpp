// `grainmesh tessellate CONFIG -o OUT`: a periodic grain microstructure with phase labels,
// written as OUT/tessellation.json, OUT/tessellation.vtp, OUT/tessellation.png and
// OUT/report.json (last).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "pipelines/config.hpp"
#include "tessellate/tessellation.hpp"
#include "view/picture.hpp"

namespace grainmesh {

struct TessellateJob {
  TessellationOptions options;
  std::uint64_t seed = 1;
  int picture_width = 1200;  // pixels
};

// The keys a tessellation config may use ("*" is a phase name).
const std::vector<std::string>& tessellate_config_keys();

// A key's value that must be a positive number (ConfigError naming the key otherwise).
double positive(const Config& c, const std::string& key);
// The diagram's keys shared by 2D and 3D: tessellation.lloyd_iterations, .size_cv,
// .min_edge (default `min_edge`) and .arrangement.
struct DiagramSettings {
  int lloyd_iterations = 0;
  double size_cv = 0.0;
  double min_edge = 0.0;
  Arrangement arrangement = Arrangement::random;
};
DiagramSettings read_diagram_settings(const Config& c, double min_edge);
// The [phase.NAME] sections: fractions (one may be rest), E, nu, alpha.
std::vector<Phase> read_phases(const Config& c);

// Reads and checks a tessellation config. Throws ConfigError naming the key.
TessellateJob read_tessellate_job(const Config& config);

// Tessellates with randomness from the job's seed alone. Errors name the config key.
Tessellation run_tessellate_job(const TessellateJob& job, const Config& config);

// Refuses (ConfigError naming its fraction) a tessellation in which a phase got no grain,
// with the grain count that would give it one: the commands' check before meshing.
void check_phases_have_grains(const Tessellation& t, const TessellateJob& job, const Config& config);

// How tessellation.png is drawn: `width` pixels wide, the phases' legend, a scale bar in
// `length_unit` (empty: the config's own, unnamed).
PictureOptions tessellation_picture(const Tessellation& t, int width, const std::string& length_unit = {});

// What a tessellation should tell its user: phase fractions that missed their target by
// more than 0.01.
std::vector<std::string> tessellation_warnings(const Tessellation& t);

void run_tessellate_command(const Config& config, const std::filesystem::path& out);

}  // namespace grainmesh
