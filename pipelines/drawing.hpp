// What the tessellation's and the mesh's writers draw, plane and solid cells alike, and
// output.pictures, which says it.
#pragma once

#include <string>

#include "pipelines/config.hpp"

namespace grainmesh {

struct Drawing {
  bool pictures = true;  // tessellation.png and mesh.png (3D: sections); none for a sweep's runs
  bool detail = true;    // mesh_detail.png (2D: the cell's centre, where single elements show)
  std::string unit;      // the scale bars' length unit (empty: the config's own, unnamed)
};

// Which pictures a run draws (output.pictures): none (no PNG, and no results.vtu: what a
// sweep wants); basic (tessellation.png, mesh.png and, solved, stress_xx.png and
// results.vtu); all (also mesh_detail.png, stress_yy.png, stress_xy.png and
// displacement.png), the default. true and false are all and none.
enum class Pictures { none, basic, all };
Pictures read_pictures(const Config& c);

// What `grainmesh tessellate` and `mesh` draw: their pictures unless output.pictures = none.
Drawing stage_drawing(const Config& c);

}  // namespace grainmesh
