// What the tessellation's and the mesh's writers draw, plane and solid cells alike.
#pragma once

#include <string>

namespace grainmesh {

struct Drawing {
  bool pictures = true;  // tessellation.png and mesh.png (3D: sections); none for a sweep's runs
  bool detail = true;    // mesh_detail.png (2D: the cell's centre, where single elements show)
  std::string unit;      // the scale bars' length unit (empty: the config's own, unnamed)
};

}  // namespace grainmesh
