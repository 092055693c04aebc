// A label image (label_image.hpp) as our tessellation: grains are the connected regions of
// one label (4-connected; across the image's borders too when it is periodic), their
// boundaries traced on the pixel lattice once for both sides, so neighbours share their
// vertices exactly, then simplified to a tolerance in pixels without any boundary crossing
// another or passing over a grain (topology kept). Grains below a size are merged into the
// neighbour they share most boundary with, or refused with their count. Phases come from
// a table of labels, or by our rules. Everything downstream takes the result unchanged.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/random.hpp"
#include "tessellate/label_image.hpp"
#include "tessellate/read_tessellation.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

struct ImageTessellationOptions {
  double pixel_size = 1.0;   // the length of a pixel's side, the caller's unit
  double tolerance = 1.0;    // how far (pixels) a simplified boundary may leave the traced one
  int min_grain_pixels = 4;  // grains of fewer pixels are merged or refused
  bool merge_small = false;  // merge them (else refuse the image)
  bool periodic = false;     // the image wraps round: its opposite borders touch
  std::vector<Phase> phases;
  std::vector<LabelPhase> label_phases;  // colours 0xRRGGBB in a colour image; empty: by our rules
  Arrangement arrangement = Arrangement::random;
};

// Grains below ImageTessellationOptions::min_grain_pixels, not to be merged.
struct SmallGrainsError : GeometryError {
  using GeometryError::GeometryError;
};

// A label as people read it: a number, or #rrggbb in a colour image.
std::string label_text(std::uint32_t label, bool colour);

// The tessellation of `image` in a cell of width x height pixels x pixel_size. Throws
// GeometryError "SOURCE: what is wrong" for small grains not to be merged, a label with no
// phase in the table, or an image of one grain.
Tessellation image_tessellation(const LabelImage& image, const ImageTessellationOptions& o, Rng& rng,
                                const std::string& source);

}  // namespace grainmesh
