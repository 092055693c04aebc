#include "pipelines/homogenise.hpp"

#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/process.hpp"

namespace grainmesh {

namespace {

struct Moduli {
  double M, K, mu;                // sigma_xx/eps_xx at eps_yy = 0; 2D bulk; shear
  double s_xx, s_xy;              // in-plane compliance
};

Moduli moduli(const FoamPhase& p, bool plane_stress) {
  const double E = p.youngs_modulus, nu = p.poisson_ratio;
  const double mu = E / (2 * (1 + nu));
  const double lambda = plane_stress ? E * nu / (1 - nu * nu) : E * nu / ((1 + nu) * (1 - 2 * nu));
  return {lambda + 2 * mu, lambda + mu, mu, plane_stress ? 1 / E : (1 - nu * nu) / E,
          plane_stress ? -nu / E : -nu * (1 + nu) / E};
}

// The cell values of an ASCII field file written by OpenFOAM: a stream at the first
// value's opening parenthesis, and their count. `type` is the list's element type.
std::istringstream cell_values(const std::filesystem::path& file, const std::string& type, std::size_t& n) {
  const std::string text = read_text_file(file, "the solver's result");
  const std::string list = "List<" + type + ">";
  const auto at = text.find(list);
  if (at == std::string::npos) throw GeometryError(file.string() + ": no cell values");
  std::istringstream in(text.substr(at + list.size()));
  char paren = 0;
  in >> n >> paren;
  return in;
}

}  // namespace

ElasticBounds elastic_bounds(const std::vector<FoamPhase>& phases, const std::vector<double>& fractions,
                             bool plane_stress) {
  ElasticBounds b;
  double s_xx = 0.0, s_xy = 0.0;
  std::vector<Moduli> m;
  for (std::size_t p = 0; p < phases.size(); ++p) {
    m.push_back(moduli(phases[p], plane_stress));
    b.voigt += fractions[p] * m.back().M;
    s_xx += fractions[p] * m.back().s_xx;
    s_xy += fractions[p] * m.back().s_xy;
  }
  // Uniform stress (sx, sy) with the mean eps_yy = s_xy sx + s_yy sy zero; s_yy = s_xx.
  b.reuss = 1.0 / (s_xx - s_xy * s_xy / s_xx);
  if (phases.size() == 2) {
    // Two-dimensional Hashin-Shtrikman bounds on K and mu, for well-ordered phases.
    const int hard = m[0].mu >= m[1].mu ? 0 : 1, soft = 1 - hard;
    if (m[hard].K >= m[soft].K) {
      auto bound = [&](int ref, int other) {
        const Moduli& r = m[ref];
        const Moduli& o = m[other];
        const double fr = fractions[ref], fo = fractions[other];
        const double K = o.K == r.K ? r.K : r.K + fo / (1 / (o.K - r.K) + fr / (r.K + r.mu));
        const double mu =
            o.mu == r.mu ? r.mu : r.mu + fo / (1 / (o.mu - r.mu) + fr * (r.K + 2 * r.mu) / (2 * r.mu * (r.K + r.mu)));
        return K + mu;
      };
      b.hs_upper = bound(hard, soft);
      b.hs_lower = bound(soft, hard);
    }
  }
  return b;
}

std::vector<CellStress> read_cell_stress(const std::filesystem::path& sigma_file) {
  std::size_t n = 0;
  std::istringstream in = cell_values(sigma_file, "symmTensor", n);
  std::vector<CellStress> out(n);
  char paren = 0;
  for (CellStress& c : out) {  // (xx xy xz yy yz zz)
    double xz, yz, zz;
    in >> paren >> c.xx >> c.xy >> xz >> c.yy >> yz >> zz >> paren;
  }
  if (!in) throw GeometryError(sigma_file.string() + ": unreadable cell values");
  return out;
}

std::vector<double> read_cell_displacement(const std::filesystem::path& d_file) {
  std::size_t n = 0;
  std::istringstream in = cell_values(d_file, "vector", n);
  std::vector<double> out(n);
  char paren = 0;
  for (double& d : out) {  // (x y z)
    double x, y, z;
    in >> paren >> x >> y >> z >> paren;
    d = std::sqrt(x * x + y * y + z * z);
  }
  if (!in) throw GeometryError(d_file.string() + ": unreadable cell values");
  return out;
}

Homogenised solve_and_homogenise(const std::filesystem::path& case_dir, const ExportMesh& m, const FoamOptions& o,
                                 const Deadline& deadline) {
  if (std::system("command -v solidDisplacementFoam > /dev/null 2>&1") != 0)
    throw IoError("--solve: solidDisplacementFoam is not installed (Debian package openfoam; scripts/install-deps.sh)");
  const std::filesystem::path log = case_dir / "log.solidDisplacementFoam";
  setenv("WM_PROJECT_DIR", "/usr/share/openfoam", /*overwrite=*/0);  // OpenFOAM's programs need it
  const int status = run_child({"solidDisplacementFoam"}, case_dir, log, deadline, "solidDisplacementFoam");
  const std::string text = read_text_file(log, "the solver's log");
  if (status != 0 || text.find("\nEnd") == std::string::npos)
    throw GeometryError("--solve: solidDisplacementFoam failed; see " + log.string());

  Homogenised h;
  const std::regex residual(R"(Solving for D([xy]), Initial residual = ([0-9.eE+-]+))");
  double last[2] = {0.0, 0.0};
  for (auto it = std::sregex_iterator(text.begin(), text.end(), residual); it != std::sregex_iterator(); ++it) {
    const int c = (*it)[1] == "x" ? 0 : 1;
    last[c] = std::stod((*it)[2]);
    h.corrections += c == 0 ? 1 : 0;
  }
  h.final_residual = std::max(last[0], last[1]);
  if (!(h.final_residual < 1e-8))
    throw GeometryError("--solve: solidDisplacementFoam stopped at residual " + to_text(h.final_residual) +
                        " after " + std::to_string(h.corrections) + " corrections, above 1e-8; see " + log.string());

  // Cell k is triangle k.
  const std::vector<CellStress> sigma = read_cell_stress(case_dir / "1" / "sigma");
  if (sigma.size() != m.mesh.triangles.size())
    throw GeometryError((case_dir / "1/sigma").string() + ": " + std::to_string(sigma.size()) + " cells, the mesh has " +
                        std::to_string(m.mesh.triangles.size()));
  double area = 0.0;
  for (std::size_t k = 0; k < sigma.size(); ++k) {
    const double a = triangle_area(m.mesh, static_cast<int>(k));
    h.sigma_xx += a * sigma[k].xx;
    h.sigma_yy += a * sigma[k].yy;
    h.sigma_xy += a * sigma[k].xy;
    area += a;
  }
  h.sigma_xx /= area;
  h.sigma_yy /= area;
  h.sigma_xy /= area;
  // Left held, right moved by the displacement (or its jump across a cyclic pair): the
  // mean of d(ux)/dx over the cell is exactly displacement / width.
  h.strain_xx = o.displacement / m.cell.width();
  h.modulus = h.sigma_xx / h.strain_xx;
  return h;
}

}  // namespace grainmesh
