// Pictures of meshes (PNG, drawn with cairo), so a user sees what was made.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/geometry.hpp"
#include "mesh/cell_mesh.hpp"
#include "mesh/trimesh.hpp"
#include "tessellate/tessellation.hpp"

namespace grainmesh {

struct PictureOptions {
  int width_px = 1200;  // image width; the height follows the mesh's aspect ratio
  int margin_px = 20;
  // #T labels (e.g. phases) filling the triangles: 0 grey-blue, 1 orange, further labels
  // from a fixed palette; empty: all 0.
  std::vector<int> fill_by{};
  std::vector<int> outline_by{};  // #T labels (e.g. grains): thick lines where they differ; empty = fill_by
  std::optional<Box> view{};      // draw only this window (a detail); default = the whole mesh
  // #T brightness factors in (0, 1] (a 3D view's lit sides); empty: all 1.
  std::vector<double> shade{};
  // The thin lines along every triangle's edges (when long enough to see); off for cells
  // cut into triangles only to be drawn.
  bool mesh_edges = true;
  // A field to show instead of fill_by: one value per triangle, coloured (viridis)
  // from its 1st to its 99th percentile, with a ticked colour bar titled `field_name`
  // below.
  std::vector<double> field{};
  std::string field_name{};
  // A signed field (a stress component): a diverging map instead, blue below zero, white
  // at zero, red above, over a range symmetric about zero (the larger of the 1st and 99th
  // percentiles' magnitudes), so that tension and compression read apart at a glance.
  bool signed_field = false;
  // Below the picture: the name of each fill_by label's colour (a legend; labels drawn,
  // not a field), and a scale bar labelled in `length_unit` (e.g. "µm"; empty: the
  // number alone, in the caller's unit).
  std::vector<std::string> legend{};
  bool scale_bar = false;
  std::string length_unit{};
};

// A label's fill colour (red, green, blue in [0, 1]), as fill_by draws it.
std::array<double, 3> label_colour(int label);

// The name of a length unit of `metres` metres (1e-6: "µm", also nm, mm, m; otherwise
// "x <metres> m").
std::string length_unit_name(double metres);
// A scale bar's length: the largest 1, 2 or 5 times a power of ten not above `longest`.
double scale_bar_length(double longest);
// Ticks for a colour bar or a plot's axis: the multiples of a step of 1, 2 or 5 times a
// power of ten in [lo, hi], three to seven of them (nearest five; lo and hi where no step
// gives three).
std::vector<double> nice_ticks(double lo, double hi);

// Triangles filled by label (fill_by) or by a field, thin mesh edges when they are at
// least a few pixels long, and thick lines along the mesh boundary and between labels
// (outline_by). Throws IoError when the file cannot be written, also for label or field
// arrays not of one value per triangle; GeometryError for an empty mesh (nothing to draw).
void write_mesh_png(const std::filesystem::path& file, const TriMesh& mesh, const PictureOptions& options = {});
// The same for polygonal cells.
void write_mesh_png(const std::filesystem::path& file, const CellMesh& mesh, const PictureOptions& options = {});

// The cell with its regions filled by phase (holes left open), grain boundaries in thin
// dark lines and the cell's sides in a thick one. Throws IoError, or GeometryError for an
// empty tessellation.
void write_tessellation_png(const std::filesystem::path& file, const Tessellation& t,
                            const PictureOptions& options = {});

// A 2D plot: series of points (markers) or polylines, with axes, ticks and a legend.
struct PlotSeries {
  std::string name;     // empty: drawn, but not in the legend
  std::vector<Vec2> points;
  bool line = false;    // a polyline through the points (in their order), dashed
  int colour = 0;       // index into a fixed palette
  std::vector<double> error{};  // points: a bar of +- this at each (e.g. a 95 % CI); empty: none
};
struct Plot {
  std::string x_label, y_label;
  std::vector<PlotSeries> series;
  int width_px = 900, height_px = 600;
};
// Throws IoError when the file cannot be written or nothing is to be drawn.
void write_plot_png(const std::filesystem::path& file, const Plot& plot);

}  // namespace grainmesh
