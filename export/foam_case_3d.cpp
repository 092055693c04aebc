#include <string>

#include "common/errors.hpp"
#include "export/foam_3d.hpp"

namespace grainmesh {

FoamCell foam_cell(const ExportMesh3& m) { return {m.phases, m.box, m.periodic}; }

PolyMesh write_foam_case_3d(const std::filesystem::path& dir, const ExportMesh3& m, const FoamOptions& o) {
  if (o.plane_stress) throw ConfigError("export.plane_stress: a 3D case has no plane to hold; remove the key");
  if (o.delta_T != 0.0)
    throw ConfigError("load.delta_T: the thermal load is not yet solved on 3D cells (2D only); remove the key");
  const FoamCell cell = foam_cell(m);
  check_case(cell, m.grain, m.phase, m.mesh.tets.size(), o);
  const PolyMesh pm = build_polymesh_3d(m, o);
  std::vector<Vec3> centroid(m.mesh.tets.size());
  for (std::size_t t = 0; t < centroid.size(); ++t) {
    const std::array<int, 4>& v = m.mesh.tets[t];
    const std::vector<Vec3>& p = m.mesh.points;
    centroid[t] = tet_centroid(p[v[0]], p[v[1]], p[v[2]], p[v[3]]);
  }
  write_case_files(dir, cell, m.phase, centroid, pm, o);
  return pm;
}

}  // namespace grainmesh
