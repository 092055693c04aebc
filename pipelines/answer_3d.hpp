// A 3D solve's answer as report.json gives it (answer.hpp's for 2D): the mixed load's
// modulus, or the periodic cell's 6 x 6 stiffness with its symmetry, engineering
// constants and bounds (a broken bound a warning), and the phases' stress statistics.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/homogenise_3d.hpp"
#include "pipelines/answer.hpp"
#include "tessellate/tessellation_3d.hpp"

namespace grainmesh {

// What a 3D solve works on: the run's staging directory `dir` (the cases in it), the
// exported mesh and the mesh its cases were written on, the export's options, the run's
// time limit.
struct SolveInput3 {
  const std::filesystem::path& dir;
  const StagedOutput& staged;
  const Tessellation3& t;
  const ExportMesh3& e;
  const FoamMesh3& fm;
  const FoamOptions& foam;
  const Deadline& deadline;
  int picture_width = 0;   // the stress sections' (0: none)
  double section_z = 0.0;  // their plane, mesh units
  std::string unit{};      // their scale bar's length unit
};


// The mixed load's answer (case/): effective.modulus (under uniaxial strain), with the
// Voigt and Reuss tensors' C11 around it and the phases' stresses; pictures of the
// section z = section_z: stress_xx.png and von_mises.png.
Answer homogenise_mixed_3d(const SolveInput3& in, std::vector<std::string>& warnings);

// The six periodic load cases' answer (case_NAME/): effective.stiffness (Cij, i <= j, each
// the mean of Cij and Cji), effective.symmetry_error, the engineering constants, the
// Voigt and Reuss tensors and the Hashin-Shtrikman bounds on bulk and shear modulus, and
// the phases' stresses per load case; the xx case's section pictures as the mixed load's.
// Under a temperature change (foam.delta_T) also the thermal case (case_thermal/): the
// effective thermal expansion tensor with Levin's exact relation beside it (more than 1 %
// off a warning), the free state's phase stresses (stresses.thermal: the residual stress;
// stresses.thermal_xx: cooled, then pulled as the xx case) and its section pictures
// (stress_xx_thermal.png, von_mises_thermal.png).
Answer homogenise_periodic_3d(const SolveInput3& in, std::vector<std::string>& warnings);

}  // namespace grainmesh
