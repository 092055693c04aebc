// Label images as they are read: one integer per pixel (a grain's or a phase's label),
// from PNG or TIFF files (8 or 16 bits, grey or colour) through VTK's readers. Rows run
// upwards: pixel (i, j) covers [i, i + 1] x [j, j + 1] in pixel units, j = 0 the image's
// bottom row. image_tessellation.hpp makes our tessellation of one.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "tessellate/tessellation.hpp"

namespace grainmesh {

struct LabelImage {
  int width = 0;                      // pixels along x
  int height = 0;                     // pixels along y
  bool colour = false;                // labels are 0xRRGGBB colours (an RGB or RGBA file); else grey values
  std::vector<std::uint32_t> labels;  // width x height, row by row from the bottom
  std::uint32_t at(int i, int j) const { return labels[static_cast<std::size_t>(j) * width + i]; }
};

// Reads a PNG or TIFF file. Throws IoError when it cannot be opened, GeometryError
// "FILE: what is wrong" when it is not a PNG or TIFF image, or not of 8- or 16-bit grey,
// grey + alpha, RGB or RGBA pixels (alpha ignored).
LabelImage read_label_image(const std::filesystem::path& file);

// Writes a grey image of 16-bit labels (a label above 65535 throws GeometryError), PNG or
// TIFF by the file's extension (.png, .tif, .tiff). For tests and benchmarks drawing
// images from known tessellations.
void write_label_image(const std::filesystem::path& file, const LabelImage& image);

// The tessellation drawn as a label image `width` pixels wide (square pixels, the height
// rounded to whole ones): each pixel labelled grain id + 1 of the region holding its centre.
LabelImage draw_label_image(const Tessellation& t, int width);

}  // namespace grainmesh
