#include "pipelines/drawing.hpp"

namespace grainmesh {

Pictures read_pictures(const Config& c) {
  if (!c.has("output.pictures")) return Pictures::all;
  const std::string p = c.text("output.pictures");
  if (p == "none" || p == "false") return Pictures::none;
  if (p == "basic") return Pictures::basic;
  if (p == "all" || p == "true") return Pictures::all;
  c.fail("output.pictures", "must be none, basic or all, got '" + p + "'");
}

Drawing stage_drawing(const Config& c) {
  const Pictures p = read_pictures(c);
  return {.pictures = p != Pictures::none, .detail = p == Pictures::all, .unit = {}};
}

}  // namespace grainmesh
