#include <cairo.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

#include "common/errors.hpp"
#include "view/picture.hpp"

namespace grainmesh {
namespace {

struct Rgb {
  double r, g, b;
};

// The series' colours (Okabe-Ito), by PlotSeries::colour.
constexpr std::array<Rgb, 6> kPalette{
    {{0.00, 0.45, 0.70}, {0.84, 0.37, 0.00}, {0.00, 0.62, 0.45}, {0.80, 0.47, 0.65}, {0.35, 0.35, 0.35}, {0.90, 0.62, 0.00}}};

// The data's range, error bars included, with some air around it (and a range even for a
// single value); the plot area in pixels; data to pixels.
struct PlotFrame {
  Box data;
  double left, right, top, bottom;
  Vec2 px(Vec2 p) const {
    return Vec2{left + (p.x - data.lo.x) / data.width() * (right - left),
                bottom - (p.y - data.lo.y) / data.height() * (bottom - top)};
  }
};

PlotFrame plot_frame(const std::filesystem::path& file, const Plot& plot) {
  Box data;
  for (const PlotSeries& s : plot.series)
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const Vec2 p = s.points[k];
      if (!is_finite(p)) continue;
      data.extend(p);
      const double e = k < s.error.size() && std::isfinite(s.error[k]) ? s.error[k] : 0.0;
      data.extend(Vec2{p.x, p.y - e});
      data.extend(Vec2{p.x, p.y + e});
    }
  if (data.empty()) throw IoError(file.string() + ": nothing to plot");
  // Some air around the data, and a range even for a single value.
  const Vec2 pad{std::max(0.05 * data.width(), 1e-9 * std::max(1.0, std::abs(data.lo.x))),
                 std::max(0.08 * data.height(), 1e-9 * std::max(1.0, std::abs(data.lo.y)))};
  return {Box{data.lo - pad, data.hi + pad}, 90, plot.width_px - 200.0, 20, plot.height_px - 60.0};
}

// The frame with round ticks and the axes' labels.
void draw_axes(cairo_t* c, const PlotFrame& f, const Plot& plot) {
  const Box& data = f.data;
  const double left = f.left, right = f.right, top = f.top, bottom = f.bottom;
  auto px = [&](Vec2 p) { return f.px(p); };
  cairo_set_source_rgb(c, 0.1, 0.1, 0.1);
  cairo_set_line_width(c, 1.0);
  cairo_rectangle(c, left, top, right - left, bottom - top);
  cairo_stroke(c);
  char text[64];
  cairo_text_extents_t ext;
  for (const double fx : nice_ticks(data.lo.x, data.hi.x)) {
    const double x = px({fx, data.lo.y}).x;
    cairo_move_to(c, x, bottom);
    cairo_line_to(c, x, bottom + 5);
    cairo_stroke(c);
    std::snprintf(text, sizeof text, "%.4g", fx);
    cairo_text_extents(c, text, &ext);
    cairo_move_to(c, x - 0.5 * ext.x_advance, bottom + 18);
    cairo_show_text(c, text);
  }
  for (const double fy : nice_ticks(data.lo.y, data.hi.y)) {
    const double y = px({data.lo.x, fy}).y;
    cairo_move_to(c, left - 5, y);
    cairo_line_to(c, left, y);
    cairo_stroke(c);
    std::snprintf(text, sizeof text, "%.4g", fy);
    cairo_text_extents(c, text, &ext);
    cairo_move_to(c, left - 8 - ext.x_advance, y + 4);
    cairo_show_text(c, text);
  }
  cairo_move_to(c, 0.5 * (left + right) - 40, plot.height_px - 15.0);
  cairo_show_text(c, plot.x_label.c_str());
  cairo_save(c);
  cairo_move_to(c, 18, 0.5 * (top + bottom) + 60);
  cairo_rotate(c, -M_PI / 2);
  cairo_show_text(c, plot.y_label.c_str());
  cairo_restore(c);
}

// One series (a dashed line, or points with their error bars) and its legend entry at
// legend_y, which moves down when the series has a name.
void draw_series(cairo_t* c, const PlotFrame& f, const PlotSeries& s, double& legend_y) {
  const double right = f.right;
  auto px = [&](Vec2 p) { return f.px(p); };
  const Rgb col = kPalette[static_cast<std::size_t>(s.colour) % kPalette.size()];
  cairo_set_source_rgb(c, col.r, col.g, col.b);
  if (s.line) {
    const double dash[] = {6.0, 4.0};
    cairo_set_dash(c, dash, 2, 0);
    cairo_set_line_width(c, 1.5);
    bool first = true;
    for (const Vec2 p : s.points) {
      if (!is_finite(p)) continue;
      const Vec2 q = px(p);
      first ? cairo_move_to(c, q.x, q.y) : cairo_line_to(c, q.x, q.y);
      first = false;
    }
    cairo_stroke(c);
    if (!s.name.empty()) {
      cairo_move_to(c, right + 15, legend_y);
      cairo_line_to(c, right + 35, legend_y);
      cairo_stroke(c);
    }
    cairo_set_dash(c, nullptr, 0, 0);
  } else {
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const Vec2 p = s.points[k];
      if (!is_finite(p)) continue;
      const Vec2 q = px(p);
      cairo_arc(c, q.x, q.y, 3.5, 0, 2 * M_PI);
      cairo_fill(c);
      if (k < s.error.size() && std::isfinite(s.error[k]) && s.error[k] > 0.0) {
        // The bar, with caps.
        const Vec2 lo = px({p.x, p.y - s.error[k]}), hi = px({p.x, p.y + s.error[k]});
        cairo_set_line_width(c, 1.5);
        cairo_move_to(c, q.x, lo.y);
        cairo_line_to(c, q.x, hi.y);
        for (const double y : {lo.y, hi.y}) {
          cairo_move_to(c, q.x - 5, y);
          cairo_line_to(c, q.x + 5, y);
        }
        cairo_stroke(c);
      }
    }
    if (!s.name.empty()) {
      cairo_arc(c, right + 25, legend_y, 3.5, 0, 2 * M_PI);
      cairo_fill(c);
    }
  }
  if (s.name.empty()) return;  // drawn, not in the legend
  cairo_set_source_rgb(c, 0.1, 0.1, 0.1);
  cairo_move_to(c, right + 42, legend_y + 4);
  cairo_show_text(c, s.name.c_str());
  legend_y += 20;
  }

}  // namespace

void write_plot_png(const std::filesystem::path& file, const Plot& plot) {
  const PlotFrame frame = plot_frame(file, plot);
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, plot.width_px, plot.height_px), cairo_surface_destroy);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()), cairo_destroy);
  cairo_t* c = cr.get();
  cairo_set_source_rgb(c, 1, 1, 1);
  cairo_paint(c);
  cairo_select_font_face(c, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(c, 12.0);
  draw_axes(c, frame, plot);
  // The series, and the legend on the right.
  double legend_y = frame.top + 10;
  for (const PlotSeries& s : plot.series) draw_series(c, frame, s, legend_y);
  cairo_surface_flush(surface.get());
  if (cairo_surface_write_to_png(surface.get(), file.c_str()) != CAIRO_STATUS_SUCCESS)
    throw IoError(file.string() + ": cannot write PNG");
}

}  // namespace grainmesh
