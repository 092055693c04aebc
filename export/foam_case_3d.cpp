#include "export/foam_case_3d.hpp"

#include <string>

#include "common/errors.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_case.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh_3d.hpp"
#include "export/polymesh_dual_3d.hpp"

namespace grainmesh {

namespace {

// What a 3D case cannot carry, refused by name before anything is written.
void check_case_3d(const ExportMesh<3>& m, const FoamOptions& o) {
  if (o.plane_stress) throw ConfigError("export.plane_stress: a 3D case has no plane to hold; remove the key");
  check_case(foam_cell(m), m.grain, m.phase, m.mesh.tets.size(), o);
}

}  // namespace

FoamMesh3 foam_mesh(const ExportMesh<3>& m, const FoamOptions& o) {
  if (o.cells == FoamOptions::Cells::polygons) return build_dual_polymesh_3d(m, o);
  FoamMesh3 out{.mesh = build_polymesh(m, o), .grain = m.grain, .phase = m.phase, .centre = {}, .volume = {}, .corner_cell = {}, .mending = {}};
  // A tetrahedron's own: OpenFOAM's pyramids give its centroid and volume.
  for (std::size_t t = 0; t < m.mesh.tets.size(); ++t) out.corner_cell.insert(out.corner_cell.end(), 4, static_cast<int>(t));
  for (const std::array<int, 4>& v : m.mesh.tets) {
    const std::vector<Vec3>& p = m.mesh.points;
    out.centre.push_back(tet_centroid(p[v[0]], p[v[1]], p[v[2]], p[v[3]]));
    out.volume.push_back(tet_volume(p[v[0]], p[v[1]], p[v[2]], p[v[3]]));
  }
  return out;
}

FoamMesh3 write_foam_case(const std::filesystem::path& dir, const ExportMesh<3>& m, const FoamOptions& o) {
  check_case_3d(m, o);
  FoamMesh3 fm = foam_mesh(m, o);
  write_foam_case(dir, m, fm, o);
  return fm;
}

void write_foam_case(const std::filesystem::path& dir, const ExportMesh<3>& m, const FoamMesh3& fm,
                        const FoamOptions& o, const std::filesystem::path& polymesh_from) {
  check_case_3d(m, o);
  write_case_files(dir, foam_cell(m), fm.phase, fm.centre, fm.mesh, o, polymesh_from);
}

}  // namespace grainmesh
