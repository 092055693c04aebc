#include "export/abaqus_file.hpp"

#include <algorithm>
#include <cctype>

#include "common/number_text.hpp"
#include "common/text_file.hpp"

namespace grainmesh {

namespace {


// A name Abaqus takes as a label: letters, digits and underscores, starting with a letter.
std::string label(const std::string& name) {
  std::string s;
  for (char c : name) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0]))) s = "P" + s;
  return s;
}

// A set's members (1-based), 16 to a line as Abaqus reads them.
void write_set(FileText& out, const std::string& keyword, const std::vector<int>& ids) {
  out << keyword << "\n";
  for (std::size_t i = 0; i < ids.size(); ++i) out << ids[i] + 1 << (i + 1 == ids.size() || i % 16 == 15 ? "\n" : ", ");
}

// One equation per tied point and direction, its terms four to a line.
void write_equations(FileText& out, const ElementMesh& m, const std::vector<PeriodicTie>& ties, int first_reference) {
  out << "** Periodicity: u(point) - u(root) - u(RP of each axis crossed) = 0\n*Equation\n";
  for (const PeriodicTie& t : ties)
    for (int dof = 1; dof <= m.dimensions; ++dof) {
      std::vector<std::pair<int, double>> terms{{t.point + 1, 1.0}, {t.root + 1, -1.0}};
      for (int axis = 0; axis < m.dimensions; ++axis)
        if (t.across[axis]) terms.push_back({first_reference + axis, -1.0});
      out << terms.size() << "\n";
      for (std::size_t k = 0; k < terms.size(); ++k)
        out << terms[k].first << ", " << dof << ", " << terms[k].second
            << (k + 1 == terms.size() || k % 4 == 3 ? "\n" : ", ");
    }
}

}  // namespace

void write_abaqus(const std::filesystem::path& file, const ElementMesh& m, const AbaqusOptions& options) {
  static constexpr const char* kAxes[3] = {"X", "Y", "Z"};
  const int d = m.dimensions;
  const std::vector<int> grains = grains_of(m);
  FileText out;
  out << "*Heading\ngrainmesh: " << grains.size() << " grains, " << m.elements.size() << " elements"
      << (m.periodic ? ", periodic" : "") << "\n** Lengths in "
      << (options.length_unit.empty() ? "the mesh's unit" : options.length_unit)
      << "; E in Pa (a strain load gives stresses in Pa); model data only: add a *Step with your load.\n";
  if (m.periodic)
    out << "** Periodic: fix one root node (set ROOT) and load through the reference nodes RP_X, RP_Y"
        << (d == 3 ? ", RP_Z" : "") << ": the displacement of RP_A is the jump across the cell along A,\n"
        << "** e.g. a macroscopic strain E gives u(RP_X) = (E_xx, E_yx" << (d == 3 ? ", E_zx" : "") << ") * width.\n";
  out << "*Node\n";
  for (std::size_t p = 0; p < m.points.size(); ++p) {
    out << p + 1 << ", " << m.points[p].x << ", " << m.points[p].y;
    if (d == 3) out << ", " << m.points[p].z;
    out << "\n";
  }
  // The reference nodes beyond the cell's high corner, one per axis.
  const int first_reference = static_cast<int>(m.points.size()) + 1;
  if (m.periodic)
    for (int axis = 0; axis < d; ++axis) {
      out << first_reference + axis;
      for (int a = 0; a < d; ++a) out << ", " << m.cell.hi[a] + (a == axis ? 0.1 * (m.cell.hi[a] - m.cell.lo[a]) : 0.0);
      out << "\n";
    }
  out << "*Element, type=" << (d == 3 ? "C3D4" : options.plane_stress ? "CPS3" : "CPE3") << ", elset=ALL\n";
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    out << e + 1;
    for (int k = 0; k < m.corners(); ++k) out << ", " << m.elements[e][k] + 1;
    out << "\n";
  }
  std::vector<std::vector<int>> of_grain(grains.size()), of_phase(m.phases.size());
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const auto rank = std::lower_bound(grains.begin(), grains.end(), m.grain[e]) - grains.begin();
    of_grain[rank].push_back(static_cast<int>(e));
    of_phase[m.phase[e]].push_back(static_cast<int>(e));
  }
  for (std::size_t g = 0; g < grains.size(); ++g)
    write_set(out, "*Elset, elset=GRAIN_" + std::to_string(grains[g]), of_grain[g]);
  for (std::size_t p = 0; p < m.phases.size(); ++p)
    write_set(out, "*Elset, elset=PHASE_" + label(m.phases[p].name), of_phase[p]);
  const std::vector<std::vector<int>> sides = side_points(m);
  for (int s = 0; s < m.sides(); ++s) {
    std::string name = side_name(m, s);
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    write_set(out, "*Nset, nset=" + name, sides[s]);
  }
  const std::vector<PeriodicTie> ties = periodic_ties(m);
  if (m.periodic) {
    for (int axis = 0; axis < d; ++axis)
      out << "*Nset, nset=RP_" << kAxes[axis] << "\n" << first_reference + axis << "\n";
    // The low corner, the root of the high corner (tied across every axis): fixing it
    // removes the rigid translation.
    int root = 0;
    for (const PeriodicTie& t : ties)
      if (t.across[0] && t.across[1] && (d == 2 || t.across[2])) root = t.root;
    out << "*Nset, nset=ROOT\n" << root + 1 << "\n";
  }
  for (std::size_t p = 0; p < m.phases.size(); ++p) {
    const FoamPhase& phase = m.phases[p];
    out << "*Material, name=" << label(phase.name) << "\n*Elastic\n"
        << phase.youngs_modulus << ", " << phase.poisson_ratio << "\n";
    if (phase.alpha != 0.0) out << "*Expansion\n" << phase.alpha << "\n";
    out << "*Solid Section, elset=PHASE_" << label(phase.name) << ", material=" << label(phase.name) << "\n"
        << (d == 2 ? "1.\n" : ",\n");
  }
  if (m.periodic) write_equations(out, m, ties, first_reference);
  write_text_file(file, out.s);
}

}  // namespace grainmesh
