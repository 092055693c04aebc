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
  ConfigOrigin origin;       // names the key at fault in errors found while tessellating
};


// Reads and checks a tessellation config. Throws ConfigError naming the key.
TessellateJob read_tessellate_job(const Config& config);

// Tessellates with randomness from the job's seed alone. Errors name the config key.
Tessellation run_tessellate_job(const TessellateJob& job);

// Refuses (ConfigError naming its fraction) a tessellation in which a phase got no grain,
// with the grain count that would give it one: the commands' check before meshing.
void check_phases_have_grains(const Tessellation& t, const TessellateJob& job);

// How tessellation.png is drawn: `width` pixels wide, the phases' legend, a scale bar in
// `length_unit` (empty: the config's own, unnamed).
PictureOptions tessellation_picture(const Tessellation& t, int width, const std::string& length_unit = {});

// What a tessellation should tell its user: phase fractions that missed their target by
// more than 0.01.
std::vector<std::string> tessellation_warnings(const Tessellation& t);

void run_tessellate_command(const Config& config, const std::filesystem::path& out);

}  // namespace grainmesh
