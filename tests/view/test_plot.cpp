// Plots: points, lines and error bars into a PNG.
#include <catch2/catch.hpp>

#include "common/errors.hpp"
#include "helpers.hpp"
#include "view/picture.hpp"

using namespace grainmesh;

TEST_CASE("plots draw their error bars and refuse an empty plot", "[export]") {
  test::ScratchDir dir("plot");
  const std::vector<Vec2> means{{0.1, 700}, {0.25, 630}, {0.4, 540}};
  Plot plot{.x_label = "fraction", .y_label = "modulus (GPa)", .series = {{"mean", means, false, 0}}};
  write_plot_png(dir / "bare.png", plot);
  plot.series[0].error = {5, 8, 12};
  write_plot_png(dir / "bars.png", plot);
  CHECK(test::read_file(dir / "bars.png") != test::read_file(dir / "bare.png"));
  // Bars of zero (or not a number) draw nothing more.
  plot.series[0].error = {0, 0, NAN};
  write_plot_png(dir / "none.png", plot);
  CHECK(test::read_file(dir / "none.png") == test::read_file(dir / "bare.png"));
  CHECK_THROWS_AS(write_plot_png(dir / "empty.png", Plot{}), IoError);
}
