// The finite elements' part of a periodic cell's answer, one contract for 2D and 3D
// (solve_cell.hpp).
#include "analysis/fe_homogenise.hpp"
#include "export/nested_split.hpp"
#include "pipelines/result_pictures.hpp"
#include "pipelines/solve_cell.hpp"
#include "view/vtu.hpp"

namespace grainmesh {

namespace {

// Refused for memory naming the key that asked for them.
FeOptions fe_options(Solver solver) { return {.memory_mib = 0.0, .reference = solver == Solver::openfoam}; }

FeNested<3> fe_solve(const SolveInput<2>& in, const ExportMesh<2>& fine) {
  return fe_homogenise_nested(*in.fe_mesh, fine, in.foam.plane_stress, in.foam.delta_T != 0.0, fe_options(in.solver));
}

FeNested<6> fe_solve(const SolveInput<3>& in, const ExportMesh<3>& fine) {
  return fe_homogenise_nested(*in.fe_mesh, fine, in.foam.delta_T != 0.0, fe_options(in.solver));
}

// The fine level's simplices with their grains and phases (the phases' names as field
// data), in the mesh's length unit: what the answer was computed on.
void write_fe_mesh(const std::filesystem::path& file, const ExportMesh<2>& m, const std::vector<std::string>& names) {
  write_vtu(file, m.mesh, {{"grain", m.grain}, {"phase", m.phase}}, {{"phase_names", names}});
}

void write_fe_mesh(const std::filesystem::path& file, const ExportMesh<3>& m, const std::vector<std::string>& names) {
  write_tet_vtu(file, m.mesh, {{"grain", &m.grain}, {"phase", &m.phase}}, {}, {{"phase_names", names}});
}

}  // namespace

template <int D>
CellAnswer<D> fe_cell_answer(const SolveInput<D>& in, const std::vector<double>& fractions, const AnswerAdvice& advice,
                             std::optional<CellAnswer<D>> solved, std::vector<std::string>& warnings) {
  constexpr std::size_t N = voigt_size(D);
  const ExportMesh<D> fine = split_nested(*in.fe_mesh);
  const FeNested<N> solved_levels = fe_solve(in, fine);
  std::string how = D == 2 ? "the cell meshed at twice the run's element size or more, each triangle then "
                                   "split in four"
                                 : "the cell meshed at twice the run's element size or more, each tetrahedron then "
                                   "split in eight";
  if (in.refine > 0) how.append(" ").append(std::to_string(in.refine + 1)).append(" times");
  const FeLevels<N> levels = fe_levels(solved_levels.fine, solved_levels.coarse, how);
  if (in.fe_mesh_file) write_fe_mesh(in.dir / "fe_mesh.vtu", fine, phase_names(in.t.phases));
  if (in.solver == Solver::openfoam) {
    add_reference(std::get<PeriodicAnswer<N>>(solved->effective), levels, advice, warnings);
    return std::move(*solved);
  }
  CellAnswer<D> answer{.effective = {}, .phase_names = phase_names(in.t.phases), .stresses = {}};
  std::optional<PeriodicAnswer<N>> openfoam;
  if (solved) {
    openfoam = std::get<PeriodicAnswer<N>>(std::move(solved->effective));
    answer.stresses = std::move(solved->stresses);
  }
  answer.effective = fe_answer(levels, in.e.phases, fractions, in.foam, advice, warnings, std::move(openfoam));
  return answer;
}

template CellAnswer<2> fe_cell_answer(const SolveInput<2>&, const std::vector<double>&, const AnswerAdvice&,
                                      std::optional<CellAnswer<2>>, std::vector<std::string>&);
template CellAnswer<3> fe_cell_answer(const SolveInput<3>&, const std::vector<double>&, const AnswerAdvice&,
                                      std::optional<CellAnswer<3>>, std::vector<std::string>&);

}  // namespace grainmesh
