// checkMesh's geometric verdict on a 3D polyMesh, computed as OpenFOAM computes it, so that
// a builder can mend its cells before a case is written (join_cells.hpp).
#pragma once

#include <vector>

#include "common/vec3.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

// The limits the verdict uses: checkMesh's defaults (OpenFOAM v1912), the face limits a
// little inside its own so that rounding in OpenFOAM's sums cannot tip a face over.
// (checkMesh's face pyramid check, below -1e-15 m^3, cannot fail at micrometre scale and
// is not repeated.)
struct FoamCheckLimits {
  double skewness = 3.8;                // checkMesh v1912: 4 on every face, the box's sides too
  double non_orthogonality_deg = 89.0;  // checkMesh: 90, its "non-orthogonality errors"
  double aspect_ratio = 1000.0;         // checkMesh: 1000
};

// What fails: faces (a skewness or a non-orthogonality above the limits) and cells (a
// volume not positive, or an aspect ratio above the limit), by number.
struct FoamCheckFailures {
  std::vector<int> faces;
  std::vector<int> cells;
  bool empty() const { return faces.empty() && cells.empty(); }
};

// The verdict on a polyMesh with its cells' centres and volumes (foam_cell_geometry's,
// #cells each); a cyclic face judged against its partner's cell, as OpenFOAM couples them.
class FoamMeshCheck {
 public:
  FoamMeshCheck(const PolyMesh& pm, const std::vector<Vec3>& centre, const std::vector<double>& volume,
                FoamCheckLimits limits = {});
  FoamCheckFailures failures() const;
  // The cell across face f from its owner: the neighbour, a cyclic face's partner's owner,
  // or -1 on another boundary face.
  int other(int f) const;
  // Whether face f fails with its owner's centre at `owner` and the other cell's (other(f)
  // >= 0) at `across`, given in the owner's frame (a cyclic partner's shifted onto it).
  bool fails(int f, Vec3 owner, Vec3 across) const;
  // The other cell's centre in the owner's frame.
  Vec3 across(int f, Vec3 other_centre) const { return other_centre + shift_[f]; }

 private:
  const PolyMesh& pm_;
  const std::vector<Vec3>& centre_;
  const std::vector<double>& volume_;
  FoamCheckLimits limits_;
  std::vector<int> partner_;  // #faces: a cyclic face's partner face, else -1
  std::vector<Vec3> shift_;   // #faces: minus its patch's separation on a cyclic face
};

}  // namespace grainmesh
