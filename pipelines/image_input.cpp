#include "pipelines/image_input.hpp"

#include <cmath>
#include <string>

#include "common/format.hpp"
#include "pipelines/cell_config.hpp"
#include "pipelines/config_values.hpp"

namespace grainmesh {

std::vector<LabelPhase> read_label_phases(const Config& c, const std::string& key, const std::vector<Phase>& phases,
                                          bool colour) {
  std::vector<LabelPhase> out;
  const std::string text = c.text(key);
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string entry = trimmed(text.substr(start, end - start));
    start = end + 1;
    const std::size_t colon = entry.find(':');
    if (colon == std::string::npos)
      c.fail(key, "'" + entry + "' is not LABELS: PHASE (e.g. 0: Co, 1-65535: WC" +
                      (colour ? " or #ff0000: WC)" : ")"));
    const std::string labels = trimmed(entry.substr(0, colon)), name = trimmed(entry.substr(colon + 1));
    LabelPhase lp;
    lp.phase = -1;
    for (std::size_t p = 0; p < phases.size(); ++p)
      if (phases[p].name == name) lp.phase = static_cast<int>(p);
    if (lp.phase < 0)
      c.fail(key, "no phase is named '" + name + "' (add [phase." + name + "] with its fraction, E and nu)");
    auto number = [&](const std::string& t, int base) {
      std::size_t used = 0;
      unsigned long v = 0;
      try {
        v = std::stoul(t, &used, base);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != t.size() || v > 0xffffffffUL)
        c.fail(key, "'" + labels + "' is not a label, a range lo-hi or a colour #rrggbb");
      return static_cast<std::uint32_t>(v);
    };
    if (!labels.empty() && labels[0] == '#') {
      if (!colour) c.fail(key, "'" + labels + "' is a colour, but the image's pixels are grey values");
      if (labels.size() != 7) c.fail(key, "'" + labels + "' is not a colour #rrggbb");
      lp.lo = lp.hi = number(labels.substr(1), 16);
    } else {
      if (colour) c.fail(key, "'" + labels + "' is a grey value, but the image is in colour: give colours #rrggbb");
      const std::size_t dash = labels.find('-', 1);
      lp.lo = number(trimmed(labels.substr(0, dash)), 10);
      lp.hi = dash == std::string::npos ? lp.lo : number(trimmed(labels.substr(dash + 1)), 10);
      if (lp.hi < lp.lo) c.fail(key, "the range '" + labels + "' runs backwards");
    }
    out.push_back(lp);
  }
  return out;
}

// tessellation.image: the file read, its cell from the pixel size (domain.width and
// .height may be left out and must match when given), periodic only when asked.
bool read_image_input(const Config& c, ImageInput& input, TessellationOptions& o) {
  if (!c.has("tessellation.image")) {
    for (const char* key :
         {"tessellation.image_pixel_size", "tessellation.image_tolerance", "tessellation.image_min_grain",
          "tessellation.image_small_grains", "tessellation.image_phases"})
      if (c.has(key)) c.fail(key, "only used with tessellation.image");
    return false;
  }
  const std::filesystem::path file = c.text("tessellation.image");
  if (c.has("tessellation.neper"))
    c.fail("tessellation.neper", "give tessellation.neper or tessellation.image, not both");
  refuse_drawing_keys(c, "tessellation.image (" + file.string() + ")");
  try {
    input.image = read_label_image(file);
  } catch (const std::exception& e) {
    c.fail("tessellation.image", e.what());
  }
  input.file = file;
  const LabelImage& image = input.image;
  ImageTessellationOptions& io = input.options;
  if (c.has("tessellation.image_pixel_size"))
    io.pixel_size = positive(c, "tessellation.image_pixel_size");
  else if (c.has("domain.width"))
    io.pixel_size = positive(c, "domain.width") / image.width;
  else
    c.fail("tessellation.image_pixel_size", "missing: the length of a pixel's side (or give domain.width)");
  const double width = image.width * io.pixel_size, height = image.height * io.pixel_size;
  const std::string sizes = std::to_string(image.width) + " x " + std::to_string(image.height) + " pixels of " +
                            to_text(io.pixel_size) + ", " + to_text(width) + " x " + to_text(height);
  if (c.has("domain.width") && std::abs(c.number("domain.width") - width) > 1e-9 * width)
    c.fail("domain.width", "must be the image's width, " + sizes);
  if (c.has("domain.height") && std::abs(c.number("domain.height") - height) > 1e-9 * height)
    c.fail("domain.height", "must be the image's height, " + sizes);
  if (!c.has("domain.periodic"))
    c.fail("domain.periodic",
           "say whether " + file.string() + " wraps round (true: its opposite borders touch) or not (false)");
  io.periodic = c.flag("domain.periodic", false);
  io.tolerance = c.number("tessellation.image_tolerance", io.tolerance);
  if (!(io.tolerance >= 0.0 && io.tolerance <= 10.0))
    c.fail("tessellation.image_tolerance", "must lie in [0, 10] pixels, got " + c.text("tessellation.image_tolerance"));
  const long long min_grain = c.integer("tessellation.image_min_grain", io.min_grain_pixels);
  if (min_grain < 1 || min_grain > 1000000)
    c.fail("tessellation.image_min_grain", "must be between 1 and 1000000 pixels");
  io.min_grain_pixels = static_cast<int>(min_grain);
  const std::string small = c.optional_text("tessellation.image_small_grains").value_or("refuse");
  if (small != "refuse" && small != "merge")
    c.fail("tessellation.image_small_grains", "refuse or merge, got '" + small + "'");
  io.merge_small = small == "merge";
  o.width = width;
  o.height = height;
  o.periodic = io.periodic;
  o.grains = 0;  // as many as the image holds
  return true;
}

}  // namespace grainmesh
