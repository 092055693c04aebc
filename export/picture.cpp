#include "export/picture.hpp"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "common/errors.hpp"

namespace grainmesh {
namespace {

struct Rgb {
  double r, g, b;
};

// Colour-blind-safe palette (Okabe-Ito, lightened) indexed by region label.
Rgb region_colour(int region) {
  static constexpr std::array<Rgb, 8> palette{{{0.78, 0.85, 0.93},
                                               {0.98, 0.75, 0.45},
                                               {0.60, 0.85, 0.75},
                                               {0.95, 0.90, 0.55},
                                               {0.60, 0.78, 0.95},
                                               {0.95, 0.65, 0.55},
                                               {0.85, 0.70, 0.85},
                                               {0.75, 0.75, 0.75}}};
  const auto n = static_cast<int>(palette.size());
  return palette[static_cast<std::size_t>(((region % n) + n) % n)];
}

}  // namespace

void write_mesh_png(const std::filesystem::path& file, const TriMesh& mesh, const PictureOptions& options) {
  Box box;
  for (const Vec2 p : mesh.points) box.extend(p);
  if (box.empty() || mesh.triangles.empty()) throw IoError(file.string() + ": nothing to draw, the mesh is empty");

  const double inner_w = options.width_px - 2.0 * options.margin_px;
  const double scale = inner_w / std::max(box.width(), 1e-300);
  const int height = std::clamp(static_cast<int>(std::ceil(box.height() * scale)) + 2 * options.margin_px, 1, 20000);

  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, options.width_px, height), cairo_surface_destroy);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()), cairo_destroy);
  cairo_t* c = cr.get();

  cairo_set_source_rgb(c, 1, 1, 1);
  cairo_paint(c);
  // Mesh coordinates to pixels, y up.
  auto px = [&](Vec2 p) { return Vec2{options.margin_px + (p.x - box.lo.x) * scale, height - options.margin_px - (p.y - box.lo.y) * scale}; };

  // Fills without antialiasing, so that neighbouring triangles leave no seams.
  cairo_set_antialias(c, CAIRO_ANTIALIAS_NONE);
  int max_region = 0;
  for (int r : mesh.region) max_region = std::max(max_region, r);
  for (int r = 0; r <= max_region; ++r) {
    bool any = false;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (mesh.region[t] != r) continue;
      const auto& v = mesh.triangles[t];
      const Vec2 a = px(mesh.points[v[0]]), b = px(mesh.points[v[1]]), d = px(mesh.points[v[2]]);
      cairo_move_to(c, a.x, a.y);
      cairo_line_to(c, b.x, b.y);
      cairo_line_to(c, d.x, d.y);
      cairo_close_path(c);
      any = true;
    }
    if (!any) continue;
    const Rgb col = region_colour(r);
    cairo_set_source_rgb(c, col.r, col.g, col.b);
    cairo_fill(c);
  }

  cairo_set_antialias(c, CAIRO_ANTIALIAS_DEFAULT);
  cairo_set_line_cap(c, CAIRO_LINE_CAP_ROUND);
  const std::vector<MeshEdge> edges = mesh_edges(mesh);
  double mean_len = 0.0;
  for (const auto& e : edges) mean_len += norm(mesh.points[e.a] - mesh.points[e.b]);
  mean_len = mean_len / static_cast<double>(edges.size()) * scale;

  auto stroke = [&](auto&& wanted, double width, Rgb col) {
    for (const auto& e : edges) {
      if (!wanted(e)) continue;
      const Vec2 a = px(mesh.points[e.a]), b = px(mesh.points[e.b]);
      cairo_move_to(c, a.x, a.y);
      cairo_line_to(c, b.x, b.y);
    }
    cairo_set_line_width(c, width);
    cairo_set_source_rgb(c, col.r, col.g, col.b);
    cairo_stroke(c);
  };
  if (mean_len >= 3.0)
    stroke([](const MeshEdge&) { return true; }, std::clamp(mean_len / 25.0, 0.4, 1.0), {0.25, 0.25, 0.30});
  const double thick = std::clamp(mean_len / 6.0, 1.5, 3.0);
  stroke([&](const MeshEdge& e) { return e.right >= 0 && mesh.region[e.left] != mesh.region[e.right]; }, thick,
         {0.75, 0.15, 0.10});
  stroke([](const MeshEdge& e) { return e.right < 0; }, thick, {0.05, 0.05, 0.10});

  cairo_surface_flush(surface.get());
  if (cairo_surface_write_to_png(surface.get(), file.c_str()) != CAIRO_STATUS_SUCCESS)
    throw IoError(file.string() + ": cannot write PNG");
}

}  // namespace grainmesh
