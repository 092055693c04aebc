// Cell stresses that do not mix the phases. The solver's cell-centred gradient of a
// displacement with a kink at a phase interface takes neighbours from both sides, so a
// cell next to an interface gets a stress between the two phases' (the saw-tooth along
// interfaces). Here each cell's displacement gradient is fitted (weighted least squares)
// to its own phase's neighbours only - every cell sharing a corner with it - and, across
// an interface edge, to the displacement where the line between the two cells' centres
// crosses the edge, chosen so that the flux along that line is continuous (each side
// weighted by its stiffness over its distance, the phases' thermal stresses pushing
// apart along the edge's normal); then turned into stress with the cell's own Lame
// constants, less its thermal stress. The solver's own fields are left as written.
#pragma once

#include <vector>

#include "analysis/foam_fields.hpp"
#include "analysis/stress_measures.hpp"
#include "export/export_mesh.hpp"
#include "export/foam_options.hpp"

namespace grainmesh {

// One stress state per cell of `m` from the case's displacement (metres; the mesh in
// units of o.convert_to_meters). A cell whose own-phase neighbourhood cannot fix a
// gradient (fewer than two independent directions) keeps the solver's stress.
std::vector<StressState> recovered_stress(const CaseFields& fields, const ExportMesh<2>& m, const FoamOptions& o);

}  // namespace grainmesh
