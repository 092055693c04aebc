// `grainmesh tessellate CONFIG -o OUT`: a periodic grain microstructure with phase labels,
// written as OUT/tessellation.json, OUT/tessellation.vtp, OUT/tessellation.png and
// OUT/report.json (last).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "pipelines/config.hpp"
#include "pipelines/tessellate_job.hpp"
#include "tessellate/tessellation.hpp"
#include "view/picture.hpp"

namespace grainmesh {

// How tessellation.png is drawn: `width` pixels wide, the phases' legend, a scale bar in
// `length_unit` (empty: the config's own, unnamed).
PictureOptions tessellation_picture(const Tessellation& t, int width, const std::string& length_unit = {});

void run_tessellate_command(const Config& config, const std::filesystem::path& out);

}  // namespace grainmesh
