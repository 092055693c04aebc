#include "export/polymesh_files.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "export/foam_file.hpp"

namespace grainmesh {

void write_polymesh(const std::filesystem::path& dir, const PolyMesh& pm, const FoamOptions& o) {
  const bool bin = o.binary;
  const std::string loc = "constant/polyMesh";
  const double s = o.convert_to_meters;
  std::vector<double> xyz;
  xyz.reserve(6 * pm.points2d.size() + 3 * pm.points3d.size());
  if (pm.points2d.empty())
    for (const Vec3 p : pm.points3d) xyz.insert(xyz.end(), {s * p.x, s * p.y, s * p.z});
  else
    for (double z : {0.0, pm.thickness})
      for (const Vec2 p : pm.points2d) xyz.insert(xyz.end(), {s * p.x, s * p.y, s * z});
  FoamFile(dir / "points", "vectorField", loc, "points", bin).vectors(xyz).write();

  FoamFile faces(dir / "faces", bin ? "faceCompactList" : "faceList", loc, "faces", bin);
  if (bin) {
    faces.labels(pm.face_start).labels(pm.face_points);
  } else {
    faces.number(pm.faces()).text("\n(\n");
    for (int f = 0; f < pm.faces(); ++f) {
      faces.number(pm.face_start[f + 1] - pm.face_start[f]).text("(");
      for (int k = pm.face_start[f]; k < pm.face_start[f + 1]; ++k)
        faces.number(pm.face_points[k]).text(k + 1 < pm.face_start[f + 1] ? " " : ")\n");
    }
    faces.text(")\n");
  }
  faces.write();

  FoamFile(dir / "owner", "labelList", loc, "owner", bin).labels(pm.owner).write();
  FoamFile(dir / "neighbour", "labelList", loc, "neighbour", bin).labels(pm.neighbour).write();

  FoamFile boundary(dir / "boundary", "polyBoundaryMesh", loc, "boundary", false);
  boundary.number(static_cast<int>(pm.patches.size())).text("\n(\n");
  for (const PolyMesh::Patch& p : pm.patches) {
    boundary.text("    " + p.name + "\n    {\n        type            " + p.type + ";\n");
    if (p.type != "patch") boundary.text("        inGroups        List<word> 1(" + p.type + ");\n");
    boundary.text("        nFaces          ").number(p.size).text(";\n        startFace       ").number(p.start).text(";\n");
    if (p.type == "cyclic") {
      boundary.text("        matchTolerance  0.0001;\n        transform       translational;\n");
      boundary.text("        neighbourPatch  " + p.neighbour_patch + ";\n        separationVector (")
          .number(s * p.separation.x)
          .text(" ")
          .number(s * p.separation.y)
          .text(" ")
          .number(s * p.separation.z + 0.0)  // + 0: no -0
          .text(");\n");
    }
    boundary.text("    }\n");
  }
  boundary.text(")\n").write();

  FoamFile cz(dir / "cellZones", "regIOobject", loc, "cellZones", bin);
  cz.number(static_cast<int>(pm.cell_zones.size())).text("\n(\n");
  for (const auto& [name, cells] : pm.cell_zones) {
    cz.text(name + "\n{\n    type cellZone;\ncellLabels      List<label> ").labels(cells).text(";\n}\n");
  }
  cz.text(")\n").write();

  FoamFile fz(dir / "faceZones", "regIOobject", loc, "faceZones", bin);
  fz.number(static_cast<int>(pm.face_zones.size())).text("\n(\n");
  for (const PolyMesh::FaceZone& z : pm.face_zones) {
    fz.text(z.name + "\n{\n    type faceZone;\nfaceLabels      List<label> ").labels(z.faces).text(";\nflipMap         List<bool> ");
    // bools are written as labels in ASCII; binary List<bool> is one byte each
    if (bin) {
      fz.number(static_cast<int>(z.flip.size())).text("\n(");
      fz.text(std::string_view(z.flip.data(), z.flip.size())).text(")\n");
    } else {
      std::vector<int> flip(z.flip.begin(), z.flip.end());
      fz.labels(flip);
    }
    fz.text(";\n}\n");
  }
  fz.text(")\n").write();
}

}  // namespace grainmesh
