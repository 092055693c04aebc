#include "view/picture.hpp"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>

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

// A colour map of five stops, linear between them: t in [0, 1] (`fallback` for NaN).
Rgb ramp(const std::array<Rgb, 5>& stops, double t, double fallback) {
  t = std::clamp(std::isfinite(t) ? t : fallback, 0.0, 1.0) * (stops.size() - 1);
  const auto k = std::min(static_cast<std::size_t>(t), stops.size() - 2);
  const double u = t - static_cast<double>(k);
  const Rgb a = stops[k], b = stops[k + 1];
  return {a.r + u * (b.r - a.r), a.g + u * (b.g - a.g), a.b + u * (b.b - a.b)};
}

// Viridis, by five stops.
Rgb viridis(double t) {
  static constexpr std::array<Rgb, 5> stops{{{0.267, 0.005, 0.329},
                                             {0.230, 0.322, 0.546},
                                             {0.128, 0.567, 0.551},
                                             {0.369, 0.789, 0.383},
                                             {0.993, 0.906, 0.144}}};
  return ramp(stops, t, 0.0);
}

// A diverging map (after Moreland's cool-warm): blue at 0, near white at 0.5, red at 1.
Rgb cool_warm(double t) {
  static constexpr std::array<Rgb, 5> stops{{{0.230, 0.299, 0.754},
                                             {0.552, 0.690, 0.996},
                                             {0.865, 0.865, 0.865},
                                             {0.958, 0.604, 0.482},
                                             {0.706, 0.016, 0.150}}};
  return ramp(stops, t, 0.5);
}

// A field's colour at t in [0, 1] of its range.
Rgb field_colour(const PictureOptions& options, double t) { return options.signed_field ? cool_warm(t) : viridis(t); }

// A white image of a box at the asked width, mapping coordinates to pixels, y up, with
// `extra_px` more rows at the bottom (for a colour bar).
class Canvas {
 public:
  Canvas(const Box& box, const PictureOptions& options, int extra_px = 0)
      : box_(box),
        margin_(options.margin_px),
        scale_((options.width_px - 2.0 * options.margin_px) / std::max(box.width(), 1e-300)),
        extra_(extra_px),
        height_(std::clamp(static_cast<int>(std::ceil(box.height() * scale_)) + 2 * options.margin_px + extra_px, 1,
                           20000)),
        surface_(cairo_image_surface_create(CAIRO_FORMAT_RGB24, options.width_px, height_), cairo_surface_destroy),
        cr_(cairo_create(surface_.get()), cairo_destroy) {
    cairo_set_source_rgb(cr_.get(), 1, 1, 1);
    cairo_paint(cr_.get());
  }
  cairo_t* get() const { return cr_.get(); }
  double scale() const { return scale_; }
  Vec2 px(Vec2 p) const {
    return {margin_ + (p.x - box_.lo.x) * scale_, height_ - extra_ - margin_ - (p.y - box_.lo.y) * scale_};
  }
  int height() const { return height_; }
  void save(const std::filesystem::path& file) {
    cairo_surface_flush(surface_.get());
    if (cairo_surface_write_to_png(surface_.get(), file.c_str()) != CAIRO_STATUS_SUCCESS)
      throw IoError(file.string() + ": cannot write PNG");
  }

 private:
  Box box_;
  double margin_;
  double scale_;
  int extra_;
  int height_;
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface_;
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr_;
};

// The row under a picture: a scale bar in the options' length unit (left) and the
// legend of the region colours (right); `top` its upper edge in pixels.
constexpr double kKeyRow = 30.0;
bool has_key(const PictureOptions& o, bool field) { return o.scale_bar || (!field && !o.legend.empty()); }

void draw_key(cairo_t* c, const Canvas& canvas, const PictureOptions& o, double width, bool field, double top) {
  cairo_select_font_face(c, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(c, 13.0);
  const double mid = top + 0.5 * kKeyRow;
  double x = o.margin_px;
  if (o.scale_bar) {
    const double length = scale_bar_length(0.25 * width), px = length * canvas.scale();
    cairo_set_source_rgb(c, 0.05, 0.05, 0.05);
    cairo_set_line_width(c, 3.0);
    cairo_move_to(c, x, mid);
    cairo_line_to(c, x + px, mid);
    cairo_stroke(c);
    cairo_set_line_width(c, 1.5);
    for (const double at : {x, x + px}) {
      cairo_move_to(c, at, mid - 6.0);
      cairo_line_to(c, at, mid + 6.0);
    }
    cairo_stroke(c);
    char text[64];
    std::snprintf(text, sizeof text, o.length_unit.empty() ? "%g" : "%g %s", length, o.length_unit.c_str());
    cairo_move_to(c, x + px + 8.0, mid + 5.0);
    cairo_show_text(c, text);
    cairo_text_extents_t ext;
    cairo_text_extents(c, text, &ext);
    x += px + ext.x_advance + 40.0;
  }
  if (field) return;
  for (std::size_t k = 0; k < o.legend.size(); ++k) {
    const Rgb col = region_colour(static_cast<int>(k));
    cairo_rectangle(c, x, mid - 7.0, 14.0, 14.0);
    cairo_set_source_rgb(c, col.r, col.g, col.b);
    cairo_fill_preserve(c);
    cairo_set_source_rgb(c, 0.1, 0.1, 0.1);
    cairo_set_line_width(c, 1.0);
    cairo_stroke(c);
    cairo_move_to(c, x + 20.0, mid + 5.0);
    cairo_show_text(c, o.legend[k].c_str());
    cairo_text_extents_t ext;
    cairo_text_extents(c, o.legend[k].c_str(), &ext);
    x += 20.0 + ext.x_advance + 24.0;
  }
}

}  // namespace

std::array<double, 3> label_colour(int label) {
  const Rgb col = region_colour(label);
  return {col.r, col.g, col.b};
}

std::string length_unit_name(double metres) {
  static constexpr std::array<std::pair<double, const char*>, 4> units{
      {{1e-9, "nm"}, {1e-6, "\u00b5m"}, {1e-3, "mm"}, {1.0, "m"}}};
  for (const auto& [m, name] : units)
    if (std::abs(metres / m - 1.0) < 1e-9) return name;
  char text[48];
  std::snprintf(text, sizeof text, "x %.4g m", metres);
  return text;
}

double scale_bar_length(double longest) {
  if (!(longest > 0.0) || !std::isfinite(longest)) return 0.0;
  const double power = std::pow(10.0, std::floor(std::log10(longest)));
  for (const double f : {5.0, 2.0, 1.0})
    if (f * power <= longest * (1 + 1e-12)) return f * power;
  return power;
}

std::vector<double> nice_ticks(double lo, double hi) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {lo};
  // The nice step f 10^e whose count of ticks is nearest five, from three to seven; a
  // tick n f 10^e is computed as n f / 10^-e for e < 0, so that 0.3 is the double 0.3.
  auto value = [](double n, double f, int e) { return e >= 0 ? n * f * std::pow(10.0, e) : n * f / std::pow(10.0, -e); };
  const int base = static_cast<int>(std::floor(std::log10((hi - lo) / 10.0)));
  double best_f = 0.0, best_first = 0.0;
  int best_e = 0, best_count = 0;
  for (int e = base; e < base + 3; ++e)
    for (const double f : {1.0, 2.0, 5.0}) {
      const double step = value(1.0, f, e);
      const double first = std::ceil(lo / step - 1e-9);
      const int count = static_cast<int>(std::floor(hi / step + 1e-9) - first) + 1;
      if (count < 3 || count > 7) continue;
      if (best_count == 0 || std::abs(count - 5) < std::abs(best_count - 5))
        best_f = f, best_e = e, best_first = first, best_count = count;
    }
  if (best_count == 0) return {lo, hi};
  std::vector<double> ticks;
  for (int k = 0; k < best_count; ++k) ticks.push_back(value(best_first + k, best_f, best_e) + 0.0);  // no -0
  return ticks;
}

namespace {

// The 1st and 99th percentiles of a field's values (a range of 1 when they coincide).
std::pair<double, double> percentile_range(std::vector<double> v) {
  const std::size_t k = v.size() / 100;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  const double least = v[k];
  std::nth_element(v.begin(), v.end() - 1 - static_cast<std::ptrdiff_t>(k), v.end());
  double most = v[v.size() - 1 - k];
  if (!(most > least)) most = least + 1.0;
  return {least, most};
}

// The colour bar under a field: least value on the left, greatest on the right, ticked,
// with the field's name.
void draw_colour_bar(cairo_t* c, const Canvas& canvas, const PictureOptions& options, double least, double most) {
  const double x0 = options.margin_px, x1 = options.width_px - options.margin_px, y0 = canvas.height() - 56.0;
  for (int i = 0; i < 256; ++i) {
    const Rgb col = field_colour(options, i / 255.0);
    cairo_set_source_rgb(c, col.r, col.g, col.b);
    cairo_rectangle(c, x0 + (x1 - x0) * i / 256.0, y0, (x1 - x0) / 256.0 + 0.5, 14.0);
    cairo_fill(c);
  }
  cairo_set_source_rgb(c, 0.1, 0.1, 0.1);
  cairo_select_font_face(c, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(c, 12.0);
  cairo_set_line_width(c, 1.0);
  char text[64];
  cairo_text_extents_t ext;
  for (const double v : nice_ticks(least, most)) {
    const double x = x0 + (x1 - x0) * (v - least) / (most - least);
    cairo_move_to(c, x, y0 + 14.0);
    cairo_line_to(c, x, y0 + 19.0);
    cairo_stroke(c);
    std::snprintf(text, sizeof text, "%.4g", v);
    cairo_text_extents(c, text, &ext);
    cairo_move_to(c, std::clamp(x - 0.5 * ext.x_advance, x0, x1 - ext.x_advance), y0 + 31.0);
    cairo_show_text(c, text);
  }
  // The title, and what the ends mean: the colours stop at the 1st and 99th percentiles.
  const std::string title = options.field_name + "   (ends: 1st and 99th percentile, beyond in the end colours)";
  cairo_set_font_size(c, 13.0);
  cairo_text_extents(c, title.c_str(), &ext);
  // A title wider than the picture is set smaller rather than cut at its ends.
  const double room = cairo_image_surface_get_width(cairo_get_target(c)) - 8.0;
  if (ext.x_advance > room) {
    cairo_set_font_size(c, 13.0 * room / ext.x_advance);
    cairo_text_extents(c, title.c_str(), &ext);
  }
  cairo_move_to(c, 0.5 * (x0 + x1 - ext.x_advance), y0 + 49.0);
  cairo_show_text(c, title.c_str());
}

// True when the given vertices all lie beyond one side of the window `box`.
template <typename Mesh, typename Ids>
bool outside_window(const Mesh& mesh, const Box& box, const Ids& vertices) {
  bool left = true, right = true, below = true, above = true;
  for (int v : vertices) {
    const Vec2 p = mesh.points[v];
    left = left && p.x < box.lo.x;
    right = right && p.x > box.hi.x;
    below = below && p.y < box.lo.y;
    above = above && p.y > box.hi.y;
  }
  return left || right || below || above;
}


// Clips to the window and fills the cells: by the field's colour, else by fill_by.
template <typename Mesh>
void fill_mesh(cairo_t* c, const Canvas& canvas, const Mesh& mesh, const Box& box, const PictureOptions& options,
               bool field, double least, double most) {
  auto px = [&](Vec2 p) { return canvas.px(p); };
  // A detail: clip to the window, and skip what lies wholly outside it.
  const Vec2 lo = px(box.lo), hi = px(box.hi);
  cairo_rectangle(c, lo.x, hi.y, hi.x - lo.x, lo.y - hi.y);
  cairo_clip(c);

  // Adds cell t to the current path, unless it lies outside the window.
  auto trace = [&](std::size_t t) {
    const std::span<const int> v = cell_ring(mesh, t);
    if (outside_window(mesh, box, v)) return false;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const Vec2 a = px(mesh.points[v[k]]);
      k == 0 ? cairo_move_to(c, a.x, a.y) : cairo_line_to(c, a.x, a.y);
    }
    cairo_close_path(c);
    return true;
  };

  // Fills without antialiasing, so that neighbouring triangles leave no seams.
  cairo_set_antialias(c, CAIRO_ANTIALIAS_NONE);
  if (field) {
    cairo_save(c);
    for (std::size_t t = 0; t < cell_count(mesh); ++t) {
      if (!trace(t)) continue;
      const Rgb col = field_colour(options, (options.field[t] - least) / (most - least));
      const double s = options.shade.empty() ? 1.0 : options.shade[t];
      cairo_set_source_rgb(c, s * col.r, s * col.g, s * col.b);
      // A hairline of the same colour closes the seams between neighbours.
      cairo_fill_preserve(c);
      cairo_set_line_width(c, 0.5);
      cairo_stroke(c);
    }
    cairo_restore(c);
  }
  auto label = [&](std::size_t t) { return options.fill_by.empty() ? 0 : options.fill_by[t]; };
  int max_label = field ? -1 : 0;
  if (!field)
    for (int r : options.fill_by) max_label = std::max(max_label, r);
  // Each label in each brightness (one, unless shaded) filled as one path.
  std::vector<double> shades = options.shade;
  std::sort(shades.begin(), shades.end());
  shades.erase(std::unique(shades.begin(), shades.end()), shades.end());
  if (shades.empty()) shades.push_back(1.0);
  auto shade = [&](std::size_t t) { return options.shade.empty() ? 1.0 : options.shade[t]; };
  for (int r = 0; r <= max_label; ++r)
    for (const double s : shades) {
      bool any = false;
      for (std::size_t t = 0; t < cell_count(mesh); ++t) {
        if (label(t) == r && shade(t) == s && trace(t)) any = true;
      }
      if (!any) continue;
      const Rgb col = region_colour(r);
      cairo_set_source_rgb(c, s * col.r, s * col.g, s * col.b);
      cairo_fill(c);
    }

}

// The mesh's edges (thin, when they are long enough to see and no field is drawn), the
// outline between labels (outline_by, else fill_by) and the boundary.
template <typename Mesh>
void stroke_mesh(cairo_t* c, const Canvas& canvas, const Mesh& mesh, const Box& box, const PictureOptions& options,
                 bool field) {
  auto px = [&](Vec2 p) { return canvas.px(p); };
  const double scale = canvas.scale();
  auto outside = [&](std::initializer_list<int> vertices) { return outside_window(mesh, box, vertices); };
  cairo_set_antialias(c, CAIRO_ANTIALIAS_DEFAULT);
  cairo_set_line_cap(c, CAIRO_LINE_CAP_ROUND);
  const std::vector<MeshEdge> edges = mesh_edges(mesh);
  double mean_len = 0.0;
  for (const auto& e : edges) mean_len += norm(mesh.points[e.a] - mesh.points[e.b]);
  mean_len = mean_len / static_cast<double>(edges.size()) * scale;

  auto stroke = [&](auto&& wanted, double width, Rgb col) {
    for (const auto& e : edges) {
      if (!wanted(e) || outside({e.a, e.b})) continue;
      const Vec2 a = px(mesh.points[e.a]), b = px(mesh.points[e.b]);
      cairo_move_to(c, a.x, a.y);
      cairo_line_to(c, b.x, b.y);
    }
    cairo_set_line_width(c, width);
    cairo_set_source_rgb(c, col.r, col.g, col.b);
    cairo_stroke(c);
  };
  if (mean_len >= 3.0 && !field && options.mesh_edges)
    stroke([](const MeshEdge&) { return true; }, std::clamp(mean_len / 25.0, 0.4, 1.0), {0.25, 0.25, 0.30});
  const double thick = std::clamp(mean_len / 6.0, 1.5, 3.0);
  const std::vector<int>& outline = options.outline_by.empty() ? options.fill_by : options.outline_by;
  if (!outline.empty())
    stroke([&](const MeshEdge& e) { return e.right >= 0 && outline[e.left] != outline[e.right]; }, thick,
           {0.75, 0.15, 0.10});
  stroke([](const MeshEdge& e) { return e.right < 0; }, thick, {0.05, 0.05, 0.10});

}

// write_mesh_png, for triangles and for cells.
template <typename Mesh>
void draw_mesh(const std::filesystem::path& file, const Mesh& mesh, const PictureOptions& options) {
  Box box;
  for (const Vec2 p : mesh.points) box.extend(p);
  if (box.empty() || cell_count(mesh) == 0) throw GeometryError(file.string() + ": nothing to draw, the mesh is empty");
  if (options.view) {
    if (options.view->empty()) throw IoError(file.string() + ": the picture's window is empty");
    box = *options.view;
  }
  const bool field = !options.field.empty();
  auto check_size = [&](std::size_t n, const char* what) {
    if (n != 0 && n != cell_count(mesh))
      throw IoError(file.string() + ": the " + what + " has " + std::to_string(n) + " values for " +
                    std::to_string(cell_count(mesh)) + " cells");
  };
  check_size(options.field.size(), "field");
  check_size(options.fill_by.size(), "fill labelling");
  check_size(options.outline_by.size(), "outline labelling");
  check_size(options.shade.size(), "shading");
  const bool key = has_key(options, field);
  Canvas canvas(box, options, (field ? 64 : 0) + (key ? static_cast<int>(kKeyRow) : 0));
  cairo_t* c = canvas.get();
  auto px = [&](Vec2 p) { return canvas.px(p); };
  // The colour range: the field's 1st to 99th percentile, so that a few peaks (at
  // junctions) do not wash out the rest; values beyond take the end colours.
  auto [least, most] = field ? percentile_range(options.field) : std::pair{0.0, 1.0};
  if (field && options.signed_field) {  // symmetric about zero: white is zero
    const double reach = std::max({std::abs(least), std::abs(most), 1e-300});
    least = -reach, most = reach;
  }
  fill_mesh(c, canvas, mesh, box, options, field, least, most);
  stroke_mesh(c, canvas, mesh, box, options, field);
  cairo_reset_clip(c);
  if (key) draw_key(c, canvas, options, box.width(), field, px(box.lo).y + options.margin_px * 0.5);
  if (field) draw_colour_bar(c, canvas, options, least, most);
  canvas.save(file);
}

}  // namespace

void write_mesh_png(const std::filesystem::path& file, const TriMesh& mesh, const PictureOptions& options) {
  draw_mesh(file, mesh, options);
}

void write_mesh_png(const std::filesystem::path& file, const CellMesh& mesh, const PictureOptions& options) {
  draw_mesh(file, mesh, options);
}

void write_tessellation_png(const std::filesystem::path& file, const Tessellation& t, const PictureOptions& options) {
  if (t.regions.empty()) throw GeometryError(file.string() + ": nothing to draw, the tessellation is empty");
  const bool key = has_key(options, false);
  Canvas canvas(Box{{0.0, 0.0}, {t.width, t.height}}, options, key ? static_cast<int>(kKeyRow) : 0);
  cairo_t* c = canvas.get();
  cairo_set_fill_rule(c, CAIRO_FILL_RULE_EVEN_ODD);  // holes of matrix regions stay open
  for (const Region& r : t.regions) {
    for (const auto& ring : r.rings) {
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Vec2 p = canvas.px(t.vertices[ring[k]]);
        k == 0 ? cairo_move_to(c, p.x, p.y) : cairo_line_to(c, p.x, p.y);
      }
      cairo_close_path(c);
    }
    const Rgb col = region_colour(r.phase);
    cairo_set_source_rgb(c, col.r, col.g, col.b);
    cairo_fill(c);
  }
  cairo_set_line_cap(c, CAIRO_LINE_CAP_ROUND);
  for (bool side : {false, true}) {
    for (const TessEdge& e : t.edges) {
      if ((e.left < 0 || e.right < 0) != side) continue;
      const Vec2 a = canvas.px(t.vertices[e.v0]), b = canvas.px(t.vertices[e.v1]);
      cairo_move_to(c, a.x, a.y);
      cairo_line_to(c, b.x, b.y);
    }
    cairo_set_line_width(c, side ? 2.5 : 1.0);
    cairo_set_source_rgb(c, 0.1, 0.1, 0.15);
    cairo_stroke(c);
  }
  if (key) draw_key(c, canvas, options, t.width, false, canvas.px({0.0, 0.0}).y + options.margin_px * 0.5);
  canvas.save(file);
}

}  // namespace grainmesh
