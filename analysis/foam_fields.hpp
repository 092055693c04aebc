// Fields as OpenFOAM writes them (ASCII): the values of the cells, and of a patch's faces.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/stress_measures.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"

namespace grainmesh {

// The components of every value of a field, in OpenFOAM's order, flattened: `width`
// numbers per cell or face (scalar 1, vector 3, symmTensor 6: xx xy xz yy yz zz, tensor
// 9: xx xy xz yx yy yz zx zy zz).
struct FieldValues {
  int width = 1;
  std::vector<double> values;
  std::size_t size() const { return values.size() / static_cast<std::size_t>(width); }
  const double* operator[](std::size_t k) const { return values.data() + k * static_cast<std::size_t>(width); }
};

// The cell values of `file` (a vol field of `type`: scalar, vector, symmTensor, tensor),
// a uniform field given as `cells` copies. Throws GeometryError naming the file when it
// is unreadable or has not `cells` values.
FieldValues read_cell_field(const std::filesystem::path& file, const std::string& type, std::size_t cells);

// The face values of patch `patch` in the same file (`faces` of them). Throws
// GeometryError when the patch or its values are missing (constraint patches, such as
// cyclic or symmetryPlane, write none).
FieldValues read_patch_field(const std::filesystem::path& file, const std::string& type, const std::string& patch,
                             std::size_t faces);

// The cell fields of a solved case, read once (CASE/TIME/D and CASE/TIME/sigmaD,
// kStressField) and carried to everything that uses them: the area average, the face
// forces, the pictures, results.vtu. The stress is the whole stress: under a temperature
// change sigmaD leaves out the thermal part, threeK alpha delta_T (export/foam_material.hpp), taken
// off its diagonal here.
struct CaseFields {
  FieldValues displacement;  // vector
  FieldValues stress;        // symmTensor: xx xy xz yy yz zz
};
// Each cell's phase in cell_phase (an index into `phases`).
CaseFields read_case_fields(const std::filesystem::path& result_dir, const std::vector<FoamPhase>& phases,
                            const std::vector<int>& cell_phase, const FoamOptions& o);
// The two fields as written, of a case of `cells` cells without a temperature change.
CaseFields read_case_fields(const std::filesystem::path& result_dir, std::size_t cells);
// sum_k weight_k fields_k, of cases on one mesh: linear elasticity adds solutions.
CaseFields superposed(const std::vector<std::pair<double, const CaseFields*>>& terms);
FieldValues superposed(const std::vector<std::pair<double, const FieldValues*>>& terms);

// The solver's stress of every cell (plane stress: zz zero), and the length of the
// displacement.
std::vector<StressState> stress_states(const CaseFields& f, bool plane_stress);
std::vector<double> displacement_length(const CaseFields& f);

// The case's latest time directory: where the solver wrote its fields. Throws SolveError
// when there is none.
std::filesystem::path latest_time_dir(const std::filesystem::path& case_dir);
// Removes the case's time directories later than `time`.
void remove_times_after(const std::filesystem::path& case_dir, double time);

}  // namespace grainmesh
