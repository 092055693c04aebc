// The force a solved case carries through its faces, as solidDisplacementFoam's own
// discrete equation has it. In the compact form (2D cases, 3D polyhedra) on a face between cells P and N
//   F = gamma_f |S| snGrad(D) + S . X_f,   X = sigma - gamma grad(D),  gamma = 2 mu + lambda,
// gamma_f interpolated as the case says (harmonic or linear), snGrad with OpenFOAM's
// non-orthogonal correction from the interpolated gradient, X_f linear; in the plain form
// (3D tetrahedra, compact_normal_stress) F = S . sigma_f, sigma_f linear. At convergence
// the forces on every cell's faces add up to zero, so the force through a patch is the
// load the cell carries, and over the cell's section it is the mean stress exactly -
// unlike the area average of cell stresses, which mixes the phases next to interfaces.
//
// On a patch where OpenFOAM writes sigma's face values (a plain patch) the force is
// S . sigma_f, which is the same flux; on a cyclic patch (which writes none) it is
// computed here from the cell fields D, grad(D) and sigmaD. Through a pinned face of a
// periodic cell (export/pin_translation.hpp) it is what balances its cell's other faces.
#pragma once

#include <array>
#include <vector>

#include "analysis/foam_fields.hpp"
#include "analysis/stress_measures.hpp"
#include "common/geometry.hpp"
#include "common/vec3.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_load.hpp"
#include "export/foam_options.hpp"
#include "export/polymesh.hpp"
#include "export/polymesh_3d.hpp"

namespace grainmesh {

class DiscreteTraction {
 public:
  // The case's mesh (`pm`, built from `m` with `o`), its solved cell fields, and each
  // cyclic patch's jump in D (metres; the low patch's, the high one has its negative).
  // grad(D) only in the compact form; the plain form's force needs sigma alone.
  DiscreteTraction(const PolyMesh& pm, const ExportMesh<2>& m, const FoamOptions& o, FieldValues D, FieldValues grad_D,
                   FieldValues sigma);
  // The same for a 3D case's mesh (write_foam_case) in `cell`.
  DiscreteTraction(const FoamMesh3& m, const FoamCell& cell, const FoamOptions& o, FieldValues D, FieldValues grad_D,
                   FieldValues sigma);

  // The force (N; z zero in 2D) through face f out of its owner: internal, cyclic and
  // pinned faces.
  Vec3 face_force(int f) const;
  // The force through a side of a cyclic case's cell ("left" ... "front"): the sum over its
  // patch's faces and its pinned face's.
  Vec3 side_force(const std::string& side) const;
  // The sum of the forces out of cell c through all its faces, where every face of it is
  // internal, cyclic, pinned or empty (else NaN): zero at convergence (a pinned face's
  // cell by construction).
  Vec3 cell_imbalance(int c) const;
  // Each cell's stress as its face forces give it (2D cases): the virial (1 / V) sum over
  // its faces of (x_f - x_c) F_f, symmetrised (xx, yy, xy; zz 0), on a mesh whose faces
  // are all internal, cyclic or empty (else GeometryError). Balanced cells make it exact
  // in the sum: the cells' virials add up, area-weighted, to the forces through the sides,
  // so a phase's area mean of it is a mean stress that agrees with the cell's exactly.
  std::vector<StressState> virial_stress() const;
  // The same in full for a case of either dimension (xx xy xz yy yz zz, as OpenFOAM
  // writes a symmTensor): each phase's volume mean of it is a mean stress that agrees
  // with the forces through the sides.
  FieldValues virial_stress_tensor() const;

 private:
  // What both constructors share: the cells' centres (metres) and volumes (cubic
  // metres), their phases.
  DiscreteTraction(const PolyMesh& pm, const FoamCell& cell, const std::vector<int>& phase, const FoamOptions& o,
                   std::vector<Vec3> centre, std::vector<double> volume, FieldValues D, FieldValues grad_D,
                   FieldValues sigma);
  struct Neighbour {
    int cell = -1;
    Vec3 shift{};  // added to the neighbour's centre (metres)
    Vec3 jump{};   // D seen across the face = D of the neighbour - jump
  };
  Neighbour neighbour(int f) const;
  // The sum of the forces out of cell c through its faces but `except`; NaN where one is
  // neither internal, cyclic, pinned nor empty.
  Vec3 faces_force(int c, int except) const;
  bool pinned(int f) const;

  const PolyMesh& pm_;
  double scale_, thickness_;
  int dimensions_;
  bool compact_;
  std::vector<Vec3> centre_;          // cell centres, metres
  std::vector<double> gamma_;         // 2 mu + lambda per cell
  std::vector<double> volume_;        // cubic metres
  bool harmonic_;
  FieldValues D_, grad_, sigma_;
  std::vector<int> patch_of_face_;    // boundary faces: their patch; internal: -1
  std::vector<Vec3> jump_;            // per patch
};

// The force through a plain patch from sigma's face values written there.
Vec3 written_patch_force(const PolyMesh& pm, const ExportMesh<2>& m, const FoamOptions& o, int patch,
                         const FieldValues& sigma_on_patch);

}  // namespace grainmesh
