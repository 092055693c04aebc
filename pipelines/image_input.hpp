// A label image as a 2D cell's grains (tessellation.image and its keys), read from a
// config: the image, the cell it makes, and how it is traced; the phase table. Each throws
// ConfigError naming the key at fault.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "pipelines/config.hpp"
#include "tessellate/image_tessellation.hpp"
#include "tessellate/label_image.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

// tessellation.image: a label image read instead of grains drawn (the cell is the image
// at its pixel size; the phases from the table, or by our rules).
struct ImageInput {
  std::filesystem::path file;  // empty: none
  LabelImage image;
  ImageTessellationOptions options;  // its phases and arrangement: the job's
};

// tessellation.image read and checked; the cell's width, height and periodicity set in
// `o`. False (and the image's other keys refused) when it is not given.
bool read_image_input(const Config& c, ImageInput& input, TessellationOptions& o);

// A phase table (tessellation.image_phases, tessellation.neper_phases) under `key`:
// "LABELS: PHASE, ..." with LABELS a label, a range lo-hi or (a colour image's) a colour
// #rrggbb, each PHASE one of `phases`.
std::vector<LabelPhase> read_label_phases(const Config& c, const std::string& key, const std::vector<Phase>& phases,
                                          bool colour);

}  // namespace grainmesh
