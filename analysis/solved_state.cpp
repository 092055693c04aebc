#include "analysis/solved_state.hpp"

namespace grainmesh {

namespace {

std::vector<StressState> superposed(const std::vector<std::pair<double, const std::vector<StressState>*>>& terms) {
  std::vector<StressState> out(terms.front().second->size());
  for (const auto& [weight, states] : terms)
    for (std::size_t t = 0; t < out.size(); ++t) {
      const StressState& s = (*states)[t];
      out[t].xx += weight * s.xx, out[t].yy += weight * s.yy, out[t].zz += weight * s.zz, out[t].xy += weight * s.xy;
    }
  return out;
}

// The terms' member `part`, with their weights.
template <typename State, typename Part>
std::vector<std::pair<double, const Part*>> parts(const std::vector<std::pair<double, const State*>>& terms,
                                                  Part State::*part) {
  std::vector<std::pair<double, const Part*>> out;
  for (const auto& [weight, state] : terms) out.push_back({weight, &(state->*part)});
  return out;
}

}  // namespace

template <std::size_t N>
SolvedState<N> superposed(const std::vector<std::pair<double, const SolvedState<N>*>>& terms) {
  SolvedState<N> out;
  out.fields = superposed(parts(terms, &SolvedState<N>::fields));
  if constexpr (N == 3) out.cell_stress = superposed(parts(terms, &SolvedState<N>::cell_stress));
  out.virial_stress = superposed(parts(terms, &SolvedState<N>::virial_stress));
  return out;
}

template <std::size_t N>
std::vector<StressTensor> cell_stress_tensors(const SolvedState<N>& s, bool virial) {
  if constexpr (N == 3) {
    return stress_tensors(s.cell_stress, virial ? &s.virial_stress : nullptr);
  } else {
    const FieldValues& cells = virial ? s.virial_stress : s.fields.stress;
    std::vector<StressTensor> out;
    out.reserve(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) out.push_back(openfoam_stress(cells[c]));
    return out;
  }
}

template <std::size_t N>
void assemble_stiffness(PeriodicHomogenised<N>& h) {
  constexpr std::size_t normals = voigt_dimensions<N>();
  for (std::size_t k = 0; k < N; ++k) {
    const LoadCaseResult<N>& r = h.cases[k];
    const double e = k < normals ? r.load.strain[k] : 2.0 * r.load.strain[k];  // engineering
    for (std::size_t i = 0; i < N; ++i) {
      h.stiffness[i][k] = r.stress[i] / e;
      h.volume_average_stiffness[i][k] = r.volume_average[i] / e;
    }
  }
}

template SolvedState<3> superposed(const std::vector<std::pair<double, const SolvedState<3>*>>&);
template SolvedState<6> superposed(const std::vector<std::pair<double, const SolvedState<6>*>>&);
template std::vector<StressTensor> cell_stress_tensors(const SolvedState<3>&, bool);
template std::vector<StressTensor> cell_stress_tensors(const SolvedState<6>&, bool);
template void assemble_stiffness(PeriodicHomogenised<3>&);
template void assemble_stiffness(PeriodicHomogenised<6>&);

}  // namespace grainmesh
