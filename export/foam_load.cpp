#include "export/foam_load.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace grainmesh {

double load_strain(const FoamCell& cell, const FoamOptions& o) {
  if (o.cyclic && o.strain != std::array<double, 6>{}) {
    double largest = 0.0;
    for (double e : o.strain) largest = std::max(largest, std::abs(e));
    return largest;
  }
  if (o.traction == 0.0) return std::abs(o.displacement) / cell.size.x;
  double softest = 1e300;
  for (const FoamPhase& p : cell.phases) softest = std::min(softest, p.youngs_modulus);
  return std::abs(o.traction) / softest;
}

double thermal_strain(const FoamCell& cell, const FoamOptions& o) {
  double strain = 0.0;
  for (const FoamPhase& p : cell.phases) {
    const double free = cell.dimensions() == 3 ? p.alpha : free_expansion(p, o.plane_stress);
    strain = std::max(strain, std::abs(free * o.delta_T));
  }
  return strain;
}

std::vector<std::string> check_load(const FoamCell& cell, const FoamOptions& o) {
  if (!(o.convert_to_meters > 0.0) || !std::isfinite(o.convert_to_meters))
    throw ConfigError("export.convert_to_meters: must be positive, got " + to_text(o.convert_to_meters));
  if (!(o.thickness >= 0.0) || !std::isfinite(o.thickness))
    throw ConfigError("export.thickness: must be positive (or 0 for the mean edge length), got " + to_text(o.thickness));
  if (o.cyclic && !cell.periodic)
    throw ConfigError("export.cyclic: the mesh is not periodic (opposite sides do not match); cyclic patches need a "
                      "periodic mesh, such as grainmesh mesh makes of a periodic tessellation");
  if (o.cyclic && (o.traction != 0.0 || o.uniaxial))
    throw ConfigError(std::string(o.traction != 0.0 ? "load.traction" : "load.uniaxial") +
                      ": not with export.cyclic, whose load is a displacement jump across left/right and whose "
                      "bottom/top pair keeps the mean transverse strain zero");
  // A cell below a nanometre is a unit slip (lengths in metres read as micrometres):
  // continuum elasticity means nothing there.
  const double size = std::max({cell.size.x, cell.size.y, cell.size.z}), metres = size * o.convert_to_meters;
  const std::string in_metres = to_text(size) + " mesh units across, times export.convert_to_meters = " +
                                to_text(o.convert_to_meters) + ": " + to_text(metres) + " m";
  if (metres < 1e-9)
    throw ConfigError("export.convert_to_meters: the cell is " + in_metres +
                      ", below 1 nm: are the lengths in metres? then set export.convert_to_meters = 1");
  // Linear elasticity is a small-strain theory: a strain above 1 % is a slip too, each
  // named by the key that makes it.
  if (o.traction == 0.0 && o.displacement == 0.0 && o.delta_T == 0.0)
    throw ConfigError("load.displacement: is 0, which loads nothing");
  if (o.traction != 0.0) {
    double softest = 1e300;
    for (const FoamPhase& p : cell.phases) softest = std::min(softest, p.youngs_modulus);
    if (std::abs(o.traction) > 0.01 * softest)
      throw ConfigError("load.traction: " + to_text(o.traction) + " Pa is above 1 % of the softest phase's E (" +
                        to_text(softest) + " Pa): strains beyond linear elasticity");
  } else if (std::abs(o.displacement) > 0.01 * cell.size.x) {
    throw ConfigError("load.displacement: " + to_text(o.displacement) + " over a cell " + to_text(cell.size.x) +
                      " wide is a mean strain of " + to_text(std::abs(o.displacement) / cell.size.x, 3) +
                      ", above 1 % (linear elasticity is for small strains): give it in the mesh's units, like the cell");
  }
  // A phase's free thermal strain: cobalt cooled from sintering takes 1.4 %; 5 % is no
  // longer a small strain.
  for (const FoamPhase& p : cell.phases) {
    const double free = std::abs((cell.dimensions() == 3 ? p.alpha : free_expansion(p, o.plane_stress)) * o.delta_T);
    if (free > 0.05)
      throw ConfigError("load.delta_T: " + to_text(o.delta_T) + " K gives phase " + p.name + " (alpha " + to_text(p.alpha) +
                        " /K) a free strain of " + to_text(free, 3) +
                        ", above 5 % (linear elasticity is for small strains): check phase." + p.name + ".alpha (1/K) and load.delta_T (K)");
  }
  std::vector<std::string> warnings;
  if (metres > 1.0)
    warnings.push_back("the cell is " + in_metres +
                       ", above 1 m: grainmesh is made for microstructures; check export.convert_to_meters");
  return warnings;
}

std::array<double, 6> cyclic_strain(const FoamCell& cell, const FoamOptions& o) {
  if (o.strain != std::array<double, 6>{}) return o.strain;
  return {o.displacement / cell.size.x};
}

Vec3 cyclic_jump(const std::array<double, 6>& e, const std::string& name, const FoamCell& cell, double scale) {
  const int axis = name == "left" || name == "right" ? 0 : name == "bottom" || name == "top" ? 1 : 2;
  // Row `axis` of the symmetric strain: xx xy xz, xy yy yz, xz yz zz.
  static constexpr int kRow[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};
  const double L = cell.size[axis] * scale;
  return {e[kRow[axis][0]] * L, e[kRow[axis][1]] * L, e[kRow[axis][2]] * L};
}

}  // namespace grainmesh
