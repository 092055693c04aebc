#include "export/polymesh.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace grainmesh {

void add_zones(const std::vector<int>& grain, const std::vector<int>& phase, const std::vector<FoamPhase>& phases,
               bool grain_zones, PolyMesh& pm) {
  for (std::size_t p = 0; p < phases.size(); ++p) {
    std::vector<int> cells;
    for (int t = 0; t < pm.cells; ++t)
      if (phase[t] == static_cast<int>(p)) cells.push_back(t);
    pm.cell_zones.emplace_back(phases[p].name, std::move(cells));
  }
  if (grain_zones) {
    std::map<int, std::vector<int>> by_grain;
    for (int t = 0; t < pm.cells; ++t) by_grain[grain[t]].push_back(t);
    for (auto& [g, cells] : by_grain) pm.cell_zones.emplace_back("grain" + std::to_string(g), std::move(cells));
  }
  // faceZones: grain boundaries and phase interfaces; a face's flip says that it points
  // from the higher label to the lower.
  PolyMesh::FaceZone grains{.name = "grainBoundaries", .faces = {}, .flip = {}};
  PolyMesh::FaceZone interfaces{.name = "phaseInterfaces", .faces = {}, .flip = {}};
  for (int f = 0; f < pm.internal_faces(); ++f) {
    const int o_ = pm.owner[f], nb = pm.neighbour[f];
    if (grain[o_] != grain[nb]) {
      grains.faces.push_back(f);
      grains.flip.push_back(grain[o_] > grain[nb]);
    }
    if (phase[o_] != phase[nb]) {
      interfaces.faces.push_back(f);
      interfaces.flip.push_back(phase[o_] > phase[nb]);
    }
  }
  pm.face_zones.push_back(std::move(grains));
  pm.face_zones.push_back(std::move(interfaces));
}

int patch_index(const PolyMesh& pm, const std::string& name) {
  for (std::size_t p = 0; p < pm.patches.size(); ++p)
    if (pm.patches[p].name == name) return static_cast<int>(p);
  return -1;
}

}  // namespace grainmesh
