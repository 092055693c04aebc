#include "export/foam.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string_view>

#include <unistd.h>

#include "common/allocator.hpp"
#include "common/cell_side.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"

namespace grainmesh {
namespace {

// The side of the cell a boundary edge lies on; within 1e-9 of the cell's size, so that
// meshes whose sides were projected (domain meshes) count too.
CellSide side_of(const Box& cell, Vec2 a, Vec2 b) {
  return side_along(cell, a, b, 1e-9 * std::max(cell.width(), cell.height()));
}

// A side face: the edge a -> b runs counter-clockwise round its owner.
struct SideFace {
  int a, b, owner;
};

}  // namespace

Lame lame(const FoamPhase& p, bool plane_stress) {
  const double E = p.youngs_modulus, nu = p.poisson_ratio;
  return {plane_stress ? E * nu / ((1 + nu) * (1 - nu)) : E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
}

double thermal_stress_per_kelvin(const FoamPhase& p, bool plane_stress) {
  const double E = p.youngs_modulus, nu = p.poisson_ratio;
  return (plane_stress ? E / (1 - nu) : E / (1 - 2 * nu)) * p.alpha;
}

double free_expansion(const FoamPhase& p, bool plane_stress) {
  return plane_stress ? p.alpha : (1 + p.poisson_ratio) * p.alpha;
}

std::vector<double> thermal_stress(const ExportMesh& m, const FoamOptions& o) {
  std::vector<double> per_phase;
  for (const FoamPhase& p : m.phases) per_phase.push_back(thermal_stress_per_kelvin(p, o.plane_stress) * o.delta_T);
  std::vector<double> out(m.phase.size());
  for (std::size_t t = 0; t < out.size(); ++t) out[t] = per_phase[static_cast<std::size_t>(m.phase[t])];
  return out;
}

double stiffness_contrast(const ExportMesh& m, const FoamOptions& o) {
  double stiff_min = 1e300, stiff_max = 0.0;
  for (const FoamPhase& p : m.phases) {
    const double stiffness = lame(p, o.plane_stress).gamma();
    stiff_min = std::min(stiff_min, stiffness);
    stiff_max = std::max(stiff_max, stiffness);
  }
  return stiff_max / stiff_min;
}

bool harmonic_stiffness(const ExportMesh& m, const FoamOptions& o) {
  return o.interpolation == FoamOptions::Interpolation::harmonic ||
         (o.interpolation == FoamOptions::Interpolation::automatic && stiffness_contrast(m, o) <= 3.0);
}

ExportMesh grain_export_mesh(const Tessellation& t, const GrainMesh& m) {
  ExportMesh e{.mesh = m.mesh, .phase = m.phase, .phases = {}, .cell = Box{{0.0, 0.0}, {t.width, t.height}},
               .periodic = t.periodic};
  e.phases = foam_phases(t.phases);
  return e;
}

PolyMesh build_polymesh(const ExportMesh& m, const FoamOptions& o) {
  const TriMesh& mesh = m.mesh;
  const int n = static_cast<int>(mesh.points.size());
  PolyMesh pm;
  pm.points2d = mesh.points;
  pm.cells = static_cast<int>(mesh.triangles.size());
  const std::vector<MeshEdge> edges = mesh_edges(mesh);
  if (o.thickness > 0.0) {
    pm.thickness = o.thickness;
  } else {
    double sum = 0.0;
    for (const MeshEdge& e : edges) sum += norm(mesh.points[e.a] - mesh.points[e.b]);
    pm.thickness = edges.empty() ? 1.0 : sum / static_cast<double>(edges.size());
  }
  auto add_face = [&](std::initializer_list<int> pts, int owner) {
    pm.face_start.push_back(static_cast<int>(pm.face_points.size()));
    pm.face_points.insert(pm.face_points.end(), pts);
    pm.owner.push_back(owner);
  };

  // Internal faces in upper-triangular order: by owner, then neighbour.
  struct Internal {
    int owner, neighbour, a, b;  // a -> b counter-clockwise round the owner
  };
  std::vector<Internal> internal;
  std::array<std::vector<SideFace>, 5> sides;
  for (const MeshEdge& e : edges) {
    if (e.right < 0) {
      sides[side_of(m.cell, mesh.points[e.a], mesh.points[e.b])].push_back({e.a, e.b, e.left});
    } else if (e.left < e.right) {
      internal.push_back({e.left, e.right, e.a, e.b});
    } else {
      internal.push_back({e.right, e.left, e.b, e.a});
    }
  }
  std::sort(internal.begin(), internal.end(), [](const Internal& x, const Internal& y) {
    return x.owner != y.owner ? x.owner < y.owner : x.neighbour < y.neighbour;
  });
  pm.face_start.reserve(internal.size() + 2 * mesh.triangles.size() + 8);
  for (const Internal& f : internal) {
    add_face({f.a, f.b, f.b + n, f.a + n}, f.owner);
    pm.neighbour.push_back(f.neighbour);
  }

  // Side patches. Cyclic pairs list their faces along the side, so face i of one
  // matches face i of the other; the others by owner.
  if (o.cyclic && !m.periodic) throw ConfigError("export.cyclic: the mesh is not periodic");  // see check_load
  const bool cyclic = o.cyclic;
  // The load needs its patches: right carries it, left holds x, bottom (and top, unless
  // uniaxial) hold y. A side without mesh edges leaves the load or a rigid motion free.
  for (CellSide s : {kRight, kLeft, kBottom, kTop}) {
    if (!sides[s].empty() || (s == kTop && o.uniaxial)) continue;
    throw ConfigError(std::string("export: patch '") + side_name(s) + "' is empty: no mesh edge lies on the cell's " +
                      side_name(s) + " side (" + (is_vertical(s) ? "x = " : "y = ") + to_text(side_coordinate(m.cell, s)) + "), so " +
                      (s == kRight ? "the load has nothing to act on" : "nothing holds the cell there") +
                      "; the mesh's bounding box must have straight mesh edges on all four sides");
  }
  auto along = [&](const SideFace& f, CellSide side) {
    const Vec2 mid = 0.5 * (mesh.points[f.a] + mesh.points[f.b]);
    return is_vertical(side) ? mid.y : mid.x;
  };
  for (CellSide s : {kLeft, kRight, kBottom, kTop})
    std::sort(sides[s].begin(), sides[s].end(), [&](const SideFace& x, const SideFace& y) {
      return cyclic ? along(x, s) < along(y, s) : x.owner < y.owner;
    });
  if (cyclic) {
    if (!sides[kNoSide].empty())
      throw GeometryError("export: cyclic patches need every boundary edge on a side of the cell");
    for (CellSide s : {kLeft, kBottom}) {
      const CellSide partner = static_cast<CellSide>(s ^ 1);
      const auto& low = sides[s];
      const auto& high = sides[partner];
      const double tol = 1e-9 * std::max(m.cell.width(), m.cell.height());
      bool match = low.size() == high.size();
      for (std::size_t k = 0; match && k < low.size(); ++k) match = std::abs(along(low[k], s) - along(high[k], s)) <= tol;
      if (!match)
        throw GeometryError(std::string("export: the faces of ") + side_name(s) + " and " + side_name(partner) +
                            " do not pair (is the mesh periodic?)");
    }
  }
  const bool top_free = o.uniaxial;
  for (CellSide s : {kLeft, kRight, kBottom, kTop, kNoSide}) {
    if (s == kNoSide && sides[s].empty()) continue;
    PolyMesh::Patch p;
    p.name = side_name(s);
    p.start = pm.faces();
    p.size = static_cast<int>(sides[s].size());
    if (cyclic && s != kNoSide) {
      p.type = "cyclic";
      p.neighbour_patch = side_name(static_cast<CellSide>(s ^ 1));
      const Vec2 shift = is_vertical(s) ? Vec2{m.cell.width(), 0.0} : Vec2{0.0, m.cell.height()};
      p.separation = (s % 2 == 0) ? shift : -shift;
    } else if (s == kLeft || s == kBottom || (s == kTop && !top_free)) {
      p.type = "symmetryPlane";
    } else {
      p.type = "patch";
    }
    // A coupled face starts at the point opposite its partner's first point: the high
    // side's faces start at their other end.
    const bool high = cyclic && (s == kRight || s == kTop);
    for (const SideFace& f : sides[s])
      high ? add_face({f.b, f.b + n, f.a + n, f.a}, f.owner) : add_face({f.a, f.b, f.b + n, f.a + n}, f.owner);
    pm.patches.push_back(p);
  }
  PolyMesh::Patch empty{.name = "frontAndBack", .type = "empty", .start = pm.faces(),
                        .size = 2 * pm.cells, .neighbour_patch = {}, .separation = {}};
  for (int t = 0; t < pm.cells; ++t) {
    const auto& v = mesh.triangles[t];
    add_face({v[0], v[2], v[1]}, t);              // z = 0, facing down
  }
  for (int t = 0; t < pm.cells; ++t) {
    const auto& v = mesh.triangles[t];
    add_face({v[0] + n, v[1] + n, v[2] + n}, t);  // z = thickness, facing up
  }
  pm.patches.push_back(empty);
  pm.face_start.push_back(static_cast<int>(pm.face_points.size()));

  // Zones: a cellZone per phase (every cell in exactly one), optionally per grain.
  for (std::size_t p = 0; p < m.phases.size(); ++p) {
    std::vector<int> cells;
    for (int t = 0; t < pm.cells; ++t)
      if (m.phase[t] == static_cast<int>(p)) cells.push_back(t);
    pm.cell_zones.emplace_back(m.phases[p].name, std::move(cells));
  }
  if (o.grain_zones) {
    std::map<int, std::vector<int>> by_grain;
    for (int t = 0; t < pm.cells; ++t) by_grain[mesh.region[t]].push_back(t);
    for (auto& [g, cells] : by_grain) pm.cell_zones.emplace_back("grain" + std::to_string(g), std::move(cells));
  }
  // faceZones: grain boundaries and phase interfaces; a face's flip says that it points
  // from the higher label to the lower.
  PolyMesh::FaceZone grains{.name = "grainBoundaries", .faces = {}, .flip = {}};
  PolyMesh::FaceZone interfaces{.name = "phaseInterfaces", .faces = {}, .flip = {}};
  for (int f = 0; f < pm.internal_faces(); ++f) {
    const int o_ = pm.owner[f], nb = pm.neighbour[f];
    if (mesh.region[o_] != mesh.region[nb]) {
      grains.faces.push_back(f);
      grains.flip.push_back(mesh.region[o_] > mesh.region[nb]);
    }
    if (m.phase[o_] != m.phase[nb]) {
      interfaces.faces.push_back(f);
      interfaces.flip.push_back(m.phase[o_] > m.phase[nb]);
    }
  }
  pm.face_zones.push_back(std::move(grains));
  pm.face_zones.push_back(std::move(interfaces));
  return pm;
}

namespace {

// system/decomposeParDict: o.processes pieces, the cell cut into nx x ny blocks as near
// square as the count allows (hierarchical: Debian's OpenFOAM has no working scotch or
// metis), each cyclic face kept on one processor with its partner (fixedJump does not
// cross processors).
void write_decompose_dict(const std::filesystem::path& dir, const ExportMesh& m, const FoamOptions& o);

// The shortest text that reads back as the same double.
std::string number_text(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// One OpenFOAM file, ASCII or binary (labels int32, scalars double, little-endian).
class FoamFile {
 public:
  FoamFile(const std::filesystem::path& file, std::string_view cls, std::string_view location, std::string_view object,
           bool binary)
      : file_(file), binary_(binary) {
    out_ += "/*--------------------------------*- C++ -*----------------------------------*\\\n";
    out_ += "  Written by grainmesh\n";
    out_ += "\\*---------------------------------------------------------------------------*/\n";
    out_ += "FoamFile\n{\n    version     2.0;\n    format      ";
    out_ += binary ? "binary;\n    arch        \"LSB;label=32;scalar=64\";\n" : "ascii;\n";
    out_ += "    class       " + std::string(cls) + ";\n";
    if (!location.empty()) out_ += "    location    \"" + std::string(location) + "\";\n";
    out_ += "    object      " + std::string(object) + ";\n}\n\n";
  }

  FoamFile& text(std::string_view s) {
    out_ += s;
    return *this;
  }
  FoamFile& number(double v) { return text(number_text(v)); }
  FoamFile& number(int v) {
    char buf[16];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out_.append(buf, r.ptr);
    return *this;
  }
  // N ( ... ) of int32 labels.
  FoamFile& labels(const std::vector<int>& v) {
    number(static_cast<int>(v.size())).text("\n(");
    if (binary_) {
      raw(v.data(), v.size() * sizeof(int));
    } else {
      for (std::size_t i = 0; i < v.size(); ++i) number(v[i]).text(i + 1 < v.size() ? "\n" : "");
      if (!v.empty()) text("\n");
    }
    return text(")\n");
  }
  FoamFile& scalars(const std::vector<double>& v) {
    number(static_cast<int>(v.size())).text("\n(");
    if (binary_) {
      raw(v.data(), v.size() * sizeof(double));
    } else {
      for (double x : v) number(x).text("\n");
    }
    return text(")\n");
  }
  // Vectors given as consecutive triples.
  FoamFile& vectors(const std::vector<double>& xyz) {
    number(static_cast<int>(xyz.size() / 3)).text("\n(");
    if (binary_) {
      raw(xyz.data(), xyz.size() * sizeof(double));
    } else {
      for (std::size_t i = 0; i < xyz.size(); i += 3)
        text("(").number(xyz[i]).text(" ").number(xyz[i + 1]).text(" ").number(xyz[i + 2]).text(")\n");
    }
    return text(")\n");
  }
  bool binary() const { return binary_; }

  void write() {
    out_ += "\n// ************************************************************************* //\n";
    std::ofstream f(file_, std::ios::binary);
    f.write(out_.data(), static_cast<std::streamsize>(out_.size()));
    if (!f) throw IoError(file_.string() + ": cannot write");
  }

 private:
  void raw(const void* p, std::size_t bytes) { out_.append(static_cast<const char*>(p), bytes); }
  std::filesystem::path file_;
  bool binary_;
  std::string out_;
};

void write_polymesh(const std::filesystem::path& dir, const PolyMesh& pm, const FoamOptions& o) {
  const bool bin = o.binary;
  const std::string loc = "constant/polyMesh";
  const double s = o.convert_to_meters;
  std::vector<double> xyz;
  xyz.reserve(6 * pm.points2d.size());
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
          .text(" 0);\n");
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

// The boundary entry of a field for each patch: constraint types follow the patch.
std::string constraint_entry(const PolyMesh::Patch& p) {
  if (p.type == "symmetryPlane" || p.type == "empty" || p.type == "cyclic") return "type " + p.type + ";";
  return "";
}

// A scalar field's boundary: each patch its constraint type, or zeroGradient.
void write_scalar_boundary(FoamFile& f, const PolyMesh& pm) {
  f.text(";\n\nboundaryField\n{\n");
  for (const PolyMesh::Patch& p : pm.patches) {
    const std::string c = constraint_entry(p);
    f.text("    " + p.name + "\n    {\n        " + (c.empty() ? "type zeroGradient;" : c) + "\n    }\n");
  }
  f.text("}\n").write();
}

void write_scalar_field(const std::filesystem::path& file, const std::string& object, const std::string& dimensions,
                        const std::vector<double>& values, const PolyMesh& pm, bool binary) {
  FoamFile f(file, "volScalarField", "0", object, binary);
  f.text("dimensions      " + dimensions + ";\n\ninternalField   nonuniform List<scalar> ").scalars(values);
  write_scalar_boundary(f, pm);
}

// The same with one value in every cell.
void write_uniform_scalar_field(const std::filesystem::path& file, const std::string& object,
                                const std::string& dimensions, double value, const PolyMesh& pm) {
  FoamFile f(file, "volScalarField", "0", object, false);
  f.text("dimensions      " + dimensions + ";\n\ninternalField   uniform ").number(value);
  write_scalar_boundary(f, pm);
}

std::string dictionary_header(const std::string& location, const std::string& object) {
  return "/*--------------------------------*- C++ -*----------------------------------*\\\n"
         "  Written by grainmesh\n"
         "\\*---------------------------------------------------------------------------*/\n"
         "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       dictionary;\n"
         "    location    \"" + location + "\";\n    object      " + object + ";\n}\n\n";
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream f(file, std::ios::binary);
  f << text;
  if (!f) throw IoError(file.string() + ": cannot write");
}

void write_decompose_dict(const std::filesystem::path& dir, const ExportMesh& m, const FoamOptions& o) {
  // The factor pair whose blocks are nearest square.
  int nx = o.processes, ny = 1;
  double best = 1e300;
  for (int a = 1; a <= o.processes; ++a) {
    if (o.processes % a != 0) continue;
    const int b = o.processes / a;
    const double aspect = (m.cell.width() / a) / (m.cell.height() / b);
    const double badness = std::abs(std::log(aspect));
    if (badness < best) best = badness, nx = a, ny = b;
  }
  std::string cyclic;
  if (o.cyclic)
    cyclic = "\n// Each cyclic face on the processor of its partner: the jump of D is applied there.\n"
             "constraints\n{\n    cyclics\n    {\n        type    preservePatches;\n"
             "        patches (left right bottom top);\n    }\n}\n";
  write_text(dir / "system/decomposeParDict",
             dictionary_header("system", "decomposeParDict") + "numberOfSubdomains " + std::to_string(o.processes) +
                 ";\n\n// Blocks of the cell, as near square as the count allows.\nmethod          hierarchical;\n\n"
                 "coeffs\n{\n    n           (" + std::to_string(nx) + " " + std::to_string(ny) +
                 " 1);\n    order       xyz;\n}\n" + cyclic);
}

// Pseudo-time steps of one correction each (d2dt2 is steadyState), stopped by
// runTimeControl once OpenFOAM's own residual is below the tolerance (case_stop), or at
// `end_step`. The force through the loaded sides and the range of every displacement
// component are logged each step, for grainmesh's solve (solve_monitor.hpp).
std::string control_dict(const ExportMesh& m, const FoamOptions& o, int end_step, double tighter, int start) {
  const std::string steps = std::to_string(end_step);
  CaseStop stop = case_stop(m, o);
  stop.tolerance *= tighter;
  // The force through the loaded sides, each correction: right, and top for a cyclic case
  // (there from the stress interpolated to the faces: a measure of settling, not the answer).
  std::string range;
  for (const char* side : {"right", "top"}) {
    if (std::string(side) == "top" && !o.cyclic) continue;
    range += std::string("    force_") + side + "\n    {\n        type            surfaceFieldValue;\n"
             "        libs            (fieldFunctionObjects);\n        fields          (" + kStressField + ");\n"
             "        operation       areaIntegrate;\n        regionType      patch;\n        name            " + side +
             ";\n        writeFields     no;\n        writeToFile     no;\n        log             yes;\n    }\n";
  }
  for (const char* op : {"min", "max"})
    range += std::string("    displacement_") + op + "\n    {\n        type            volFieldValue;\n"
             "        libs            (fieldFunctionObjects);\n        fields          (D);\n"
             "        operation       " + op + ";\n        regionType      all;\n        writeFields     no;\n"
             "        writeToFile     no;\n        log             yes;\n    }\n";
  return dictionary_header("system", "controlDict") +
         "application     solidDisplacementFoam;\n\n" +
         (start == 0 ? std::string("startFrom       startTime;\nstartTime       0;\n")
                     : "// Continued from where the last run stopped.\nstartFrom       latestTime;\n") +
         "stopAt          endTime;\n// Each step is one correction of the displacement (d2dt2 steadyState): at most " +
         steps + (end_step == kMaxCorrections ? "" : ", where grainmesh's criterion was met") +
         (tighter == 1.0 ? "" : "; its own stop tightened until the effective stress settles") +
         ".\nendTime         " + steps + ";\ndeltaT          1;\n\n" +
         (o.processes > 1 ? "// Written once, when the run stops; in binary on several processes, where\n"
                            "// decomposePar and reconstructPar would spend longer than the solve on ASCII.\n"
                          : "// Written once, when the run stops. Results in ASCII whatever the mesh's format:\n"
                            "// they are what users read (grainmesh reads either).\n") +
         "writeControl    timeStep;\nwriteInterval   " + steps + ";\npurgeWrite      0;\nwriteFormat     " +
         (o.processes > 1 ? "binary" : "ascii") +
         ";\nwritePrecision  12;\nwriteCompression off;\ntimeFormat      general;\ntimePrecision   6;\n"
         "runTimeModifiable false;\n\n"
         "functions\n{\n" + range +
         "    // Stop once the displacement equation's initial residual is below the tolerance" +
         (stop.alone >= 0 ? ";\n    // the loaded component alone (at a hundredth of it): one material keeps the other exactly\n"
                            "    // zero, and its residual is noise"
                          : "") +
         ";\n    // not before the effective stress has a full window of corrections to be judged by (a\n"
         "    // solve that starts at its answer, one material, would stop at once and not be known settled).\n"
         "    converged\n    {\n        type            runTimeControl;\n        libs            (utilityFunctionObjects);\n"
         "        timeStart       " + std::to_string(start + kStressWindow + 1) + ";\n"
         "        conditions\n        {\n            residual\n            {\n"
         "                type    equationInitialResidual;\n                fields  (" +
         (stop.alone >= 0 ? "D.component(" + std::to_string(stop.alone) + ")" : std::string("D")) + ");\n"
         "                value   " + number_text(stop.tolerance) + ";\n                mode    minimum;\n"
         "            }\n        }\n    }\n" +
         "    // The stress (sigmaD; rho is 1, so it is sigma) whenever the fields are written, also\n"
         "    // when runTimeControl stops the run, where the solver itself writes no sigma.\n"
         "    stress\n    {\n        type            writeObjects;\n        libs            (utilityFunctionObjects);\n"
         "        objects         (" + std::string(kStressField) + ");\n        writeOption     anyWrite;\n        writeControl    writeTime;\n    }\n" +
         (o.cyclic ? "    // grad(D) where the fields are written: with D and sigmaD it gives the force through the\n"
                     "    // cyclic faces, where OpenFOAM writes no face values (grainmesh's homogenisation).\n"
                     "    gradient\n    {\n        type            grad;\n        libs            (fieldFunctionObjects);\n"
                     "        field           D;\n        executeControl  writeTime;\n        writeControl    writeTime;\n    }\n"
                   : "") +
         "}\n";
}

}  // namespace

std::array<double, 3> cyclic_strain(const ExportMesh& m, const FoamOptions& o) {
  if (o.strain != std::array<double, 3>{}) return o.strain;
  return {o.displacement / m.cell.width(), 0.0, 0.0};
}

std::vector<std::string> foam_environment() {
  const char* project = std::getenv("WM_PROJECT_DIR");
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::vector<std::string> env{
      "WM_PROJECT_DIR=" + std::string(project != nullptr && *project != '\0' ? project : kFoamProjectDir),
      "GLIBC_TUNABLES=" + malloc_tunables() + (tunables != nullptr && *tunables != '\0' ? ":" + std::string(tunables) : "")};
  if (geteuid() == 0) env.insert(env.end(), {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"});
  return env;
}

std::vector<std::string> solver_command(const FoamOptions& o) {
  if (o.processes <= 1) return {"solidDisplacementFoam"};
  return {"mpirun", "--oversubscribe", "-np", std::to_string(o.processes), "solidDisplacementFoam", "-parallel"};
}

CaseStop case_stop(const ExportMesh& m, const FoamOptions& o) {
  // One material under a load that moves it along one axis only: the other component is
  // exactly zero and its residual noise. Its error follows the loaded one's (its range
  // stays about ten times that one's residual, measured), so the loaded one alone at a
  // hundredth of the tolerance also meets the scale-aware criterion.
  bool one_material = true;
  for (const FoamPhase& p : m.phases)
    one_material = one_material && p.youngs_modulus == m.phases.front().youngs_modulus &&
                   p.poisson_ratio == m.phases.front().poisson_ratio;
  // A periodic case's effective stress settles later than a mixed one's (measured: at a
  // residual near 1e-7 under a normal strain, lower under shear): its stop a hundred times
  // tighter, so that it rarely needs continuing (analysis/solve.cpp).
  const double tolerance = o.cyclic ? 0.01 * kSolverTolerance : kSolverTolerance;
  // A temperature change loads both components alike.
  if (!one_material || o.delta_T != 0.0) return {.alone = -1, .tolerance = tolerance};
  if (!o.cyclic) return o.uniaxial ? CaseStop{} : CaseStop{.alone = 0, .tolerance = 0.01 * tolerance};
  const std::array<double, 3> e = cyclic_strain(m, o);
  if (e[2] != 0.0 || (e[0] != 0.0 && e[1] != 0.0)) return {.alone = -1, .tolerance = tolerance};
  return {.alone = e[0] != 0.0 ? 0 : 1, .tolerance = 0.01 * tolerance};
}

void write_control_dict(const std::filesystem::path& dir, const ExportMesh& m, const FoamOptions& o, int end_step,
                        double tighter, int start) {
  write_text(dir / "system/controlDict", control_dict(m, o, end_step, tighter, start));
}

double load_strain(const Box& cell, const std::vector<FoamPhase>& phases, const FoamOptions& o) {
  if (o.cyclic && o.strain != std::array<double, 3>{})
    return std::max({std::abs(o.strain[0]), std::abs(o.strain[1]), std::abs(o.strain[2])});
  if (o.traction == 0.0) return std::abs(o.displacement) / cell.width();
  double softest = 1e300;
  for (const FoamPhase& p : phases) softest = std::min(softest, p.youngs_modulus);
  return std::abs(o.traction) / softest;
}

double thermal_strain(const std::vector<FoamPhase>& phases, const FoamOptions& o) {
  double strain = 0.0;
  for (const FoamPhase& p : phases) strain = std::max(strain, std::abs(free_expansion(p, o.plane_stress) * o.delta_T));
  return strain;
}

std::vector<FoamPhase> foam_phases(const std::vector<Phase>& phases) {
  std::vector<FoamPhase> out;
  for (const Phase& p : phases) out.push_back({p.name, p.youngs_modulus, p.poisson_ratio, p.alpha.value_or(0.0)});
  return out;
}

std::vector<std::string> check_load(const Box& cell, bool periodic, const std::vector<FoamPhase>& phases,
                                    const FoamOptions& o) {
  if (!(o.convert_to_meters > 0.0) || !std::isfinite(o.convert_to_meters))
    throw ConfigError("export.convert_to_meters: must be positive, got " + to_text(o.convert_to_meters));
  if (!(o.thickness >= 0.0) || !std::isfinite(o.thickness))
    throw ConfigError("export.thickness: must be positive (or 0 for the mean edge length), got " + to_text(o.thickness));
  if (o.cyclic && !periodic)
    throw ConfigError("export.cyclic: the mesh is not periodic (opposite sides do not match); cyclic patches need a "
                      "periodic mesh, such as grainmesh mesh makes of a periodic tessellation");
  if (o.cyclic && (o.traction != 0.0 || o.uniaxial))
    throw ConfigError(std::string(o.traction != 0.0 ? "load.traction" : "load.uniaxial") +
                      ": not with export.cyclic, whose load is a displacement jump across left/right and whose "
                      "bottom/top pair keeps the mean transverse strain zero");
  // A cell below a nanometre is a unit slip (lengths in metres read as micrometres):
  // continuum elasticity means nothing there.
  const double size = std::max(cell.width(), cell.height()), metres = size * o.convert_to_meters;
  const std::string in_metres = to_text(size) + " mesh units across, times export.convert_to_meters = " +
                                to_text(o.convert_to_meters) + ": " + to_text(metres) + " m";
  if (metres < 1e-9)
    throw ConfigError("export.convert_to_meters: the cell is " + in_metres +
                      ", below 1 nm: are the lengths in metres? then set export.convert_to_meters = 1");
  // Linear elasticity is a small-strain theory: a mean strain above 1 % is a slip too.
  if (o.traction == 0.0 && o.displacement == 0.0 && o.delta_T == 0.0)
    throw ConfigError("load.displacement: is 0, which loads nothing");
  const double strain = load_strain(cell, phases, o);
  if (strain > 0.01 && o.traction == 0.0 && o.delta_T == 0.0)  // a thermal case's strain is the phases' own
    throw ConfigError("load.displacement: " + to_text(o.displacement) + " over a cell " + to_text(cell.width()) +
                      " wide is a mean strain of " + to_text(strain, 3) +
                      ", above 1 % (linear elasticity is for small strains): give it in the mesh's units, like the cell");
  if (strain > 0.01)
    throw ConfigError("load.traction: " + to_text(o.traction) + " Pa is above 1 % of the softest phase's E (" +
                      to_text(std::abs(o.traction) / strain) + " Pa): strains beyond linear elasticity");
  std::vector<std::string> warnings;
  if (metres > 1.0)
    warnings.push_back("the cell is " + in_metres +
                       ", above 1 m: grainmesh is made for microstructures; check export.convert_to_meters");
  return warnings;
}

PolyMesh write_foam_case(const std::filesystem::path& dir, const ExportMesh& m, const FoamOptions& o) {
  for (const FoamPhase& p : m.phases) {
    if (!(p.youngs_modulus > 0.0) || !std::isfinite(p.youngs_modulus))
      throw ConfigError("phase." + p.name + ".E: must be positive, got " + to_text(p.youngs_modulus));
    if (!(p.poisson_ratio > -1.0 && p.poisson_ratio < 0.5))
      throw ConfigError("phase." + p.name + ".nu: must lie in (-1, 0.5), got " + to_text(p.poisson_ratio));
  }
  const bool thermal = o.delta_T != 0.0;
  if (!std::isfinite(o.delta_T)) throw ConfigError("load.delta_T: must be a finite number (K), got " + to_text(o.delta_T));
  if (thermal && (!o.cyclic || o.traction != 0.0))
    throw ConfigError("load.delta_T: a thermal case is a periodic cell's cyclic case (homogenise.boundary = periodic)");
  for (const FoamPhase& p : m.phases)
    if (thermal && !(p.alpha >= 0.0 && std::isfinite(p.alpha)))
      throw ConfigError("phase." + p.name + ".alpha: must be a finite number >= 0 (1/K), got " + to_text(p.alpha));
  if (m.phase.size() != m.mesh.triangles.size()) throw GeometryError("export: the mesh needs a phase per triangle");
  for (int ph : m.phase)
    if (ph < 0 || static_cast<std::size_t>(ph) >= m.phases.size())
      throw GeometryError("export: a triangle names phase " + std::to_string(ph) + ", which does not exist");
  check_load(m.cell, m.periodic, m.phases, o);
  const PolyMesh pm = build_polymesh(m, o);
  for (const char* sub : {"constant/polyMesh", "0", "system"}) std::filesystem::create_directories(dir / sub);
  write_polymesh(dir / "constant/polyMesh", pm, o);

  const bool harmonic = harmonic_stiffness(m, o);

  // Fields from each cell's phase.
  std::vector<double> E(pm.cells), nu(pm.cells), alpha(pm.cells);
  for (int t = 0; t < pm.cells; ++t) {
    E[t] = m.phases[m.phase[t]].youngs_modulus;
    nu[t] = m.phases[m.phase[t]].poisson_ratio;
    alpha[t] = m.phases[m.phase[t]].alpha;
  }
  write_scalar_field(dir / "0/E", "E", "[1 -1 -2 0 0 0 0]", E, pm, o.binary);
  write_scalar_field(dir / "0/nu", "nu", "[0 0 0 0 0 0 0]", nu, pm, o.binary);

  // Displacement: the load on `right`, symmetry or traction-free elsewhere. The solve
  // starts from the displacement a uniform cell would take under the imposed mean strain
  // (left and bottom held): only the fluctuation is left to the corrections.
  const std::string d = number_text(o.displacement * o.convert_to_meters);
  const std::array<double, 3> mean_strain = o.cyclic ? cyclic_strain(m, o)
                                            : o.traction == 0.0
                                                ? std::array<double, 3>{o.displacement / m.cell.width(), 0.0, 0.0}
                                                : std::array<double, 3>{};
  std::vector<double> initial(3 * static_cast<std::size_t>(pm.cells), 0.0);
  for (int t = 0; t < pm.cells; ++t) {
    const Vec2 c = triangle_centroid(m.mesh, t) - m.cell.lo;
    initial[3 * t] = (mean_strain[0] * c.x + mean_strain[2] * c.y) * o.convert_to_meters;
    initial[3 * t + 1] = (mean_strain[2] * c.x + mean_strain[1] * c.y) * o.convert_to_meters;
  }
  FoamFile D(dir / "0/D", "volVectorField", "0", "D", o.binary);
  D.text("dimensions      [0 1 0 0 0 0 0];\n\ninternalField   nonuniform List<vector> ").vectors(initial);
  D.text(";\n\nboundaryField\n{\n");
  for (const PolyMesh::Patch& p : pm.patches) {
    std::string entry = constraint_entry(p);
    const std::array<double, 3>& e = mean_strain;
    const bool x_pair = p.name == "left" || p.name == "right";
    const double L = (x_pair ? m.cell.width() : m.cell.height()) * o.convert_to_meters;
    const double jump_x = (x_pair ? e[0] : e[2]) * L, jump_y = (x_pair ? e[2] : e[1]) * L;
    if (p.type == "cyclic" && (jump_x != 0.0 || jump_y != 0.0)) {
      // Periodic: D jumps across the pair by the macroscopic strain times the separation
      // (given on the low patch of the pair), so the mean strain is the one imposed.
      const bool low = p.name == "left" || p.name == "bottom";
      entry = "type            fixedJump;\n        patchType       cyclic;\n" +
              (low ? "        jump            uniform (" + number_text(jump_x) + " " + number_text(jump_y) + " 0);\n"
                   : std::string()) +
              "        value           uniform (0 0 0);";
    } else if (entry.empty() && p.name == "right" && o.traction != 0.0) {
      entry = "type            tractionDisplacement;\n        traction        uniform (" + number_text(o.traction) +
              " 0 0);\n        pressure        uniform 0;\n        value           uniform (0 0 0);";
    } else if (entry.empty() && p.name == "right") {
      // The normal component fixed, the tangential free (zero gradient).
      entry = "type            directionMixed;\n        refValue        uniform (" + d +
              " 0 0);\n        refGradient     uniform (0 0 0);\n        valueFraction   uniform (1 0 0 0 0 0);\n"
              "        value           uniform (" + d + " 0 0);";
    } else if (entry.empty()) {
      entry = "type            tractionDisplacement;\n        traction        uniform (0 0 0);\n"
              "        pressure        uniform 0;\n        value           uniform (0 0 0);";
    }
    D.text("    " + p.name + "\n    {\n        " + entry + "\n    }\n");
  }
  D.text("}\n").write();

  write_text(dir / "constant/mechanicalProperties",
             dictionary_header("constant", "mechanicalProperties") +
                 "// E and nu vary by phase: read from 0/E and 0/nu.\nrho\n{\n    type        uniform;\n"
                 "    value       1;\n}\n\nnu\n{\n    type        field;\n}\n\nE\n{\n    type        field;\n}\n\n"
                 "planeStress     " + std::string(o.plane_stress ? "yes" : "no") + ";\n");
  if (thermal) {
    // A uniform temperature change: T holds it in every cell and keeps it (its equation is
    // not iterated, see fvSolution); alpha per cell from the phases.
    write_scalar_field(dir / "0/alpha", "alpha", "[0 0 0 -1 0 0 0]", alpha, pm, o.binary);
    write_uniform_scalar_field(dir / "0/T", "T", "[0 0 0 1 0 0 0]", o.delta_T, pm);
  }
  write_text(dir / "constant/thermalProperties",
             dictionary_header("constant", "thermalProperties") +
                 (thermal ? "// The temperature change in 0/T (uniform), alpha per cell in 0/alpha. C and k only\n"
                            "// set how T would diffuse; it is uniform and stays so.\nthermalStress   yes;\n\n"
                            "C\n{\n    type        uniform;\n    value       1;\n}\n\n"
                            "k\n{\n    type        uniform;\n    value       1;\n}\n\n"
                            "alpha\n{\n    type        field;\n}\n"
                          : "thermalStress   no;\n"));
  write_control_dict(dir, m, o, kMaxCorrections);
  const std::string stiffness = harmonic
      ? "    // The stiffness interpolated harmonically across faces: exact at phase interfaces.\n"
        "    laplacian(DD,D) Gauss harmonic corrected;\n"
      : "    // The stiffness interpolated linearly: harmonic diverges at this stiffness contrast.\n"
        "    laplacian(DD,D) Gauss linear corrected;\n";
  write_text(dir / "system/fvSchemes",
             dictionary_header("system", "fvSchemes") +
                 "d2dt2Schemes\n{\n    default         steadyState;\n}\n\nddtSchemes\n{\n    default         Euler;\n}\n\n"
                 "gradSchemes\n{\n    default         leastSquares;\n" +
                 (thermal ? "    // The thermal force as a sum over faces: each cell's share of the interfaces.\n"
                            "    grad((threeKalpha*T)) Gauss linear;\n"
                          : "") +
                 "}\n\n"
                 "divSchemes\n{\n    default         none;\n    div(sigmaD)     Gauss linear;\n}\n\n"
                 "laplacianSchemes\n{\n    default         none;\n" + stiffness +
                 "    laplacian(DT,T) Gauss linear corrected;\n}\n\n"
                 "interpolationSchemes\n{\n    default         linear;\n}\n\nsnGradSchemes\n{\n    default         none;\n}\n");
  write_text(dir / "system/fvSolution",
             dictionary_header("system", "fvSolution") +
                 "solvers\n{\n    D\n    {\n        solver          GAMG;\n        tolerance       1e-12;\n"
                 "        relTol          0.1;\n        smoother        GaussSeidel;\n    }\n" +
                 (thermal ? "    // T is uniform: met at once, never iterated.\n    T\n    {\n        solver          PCG;\n"
                            "        preconditioner  none;\n        tolerance       1e300;\n        relTol          0;\n    }\n"
                          : "") +
                 "}\n\n"
                 "// One correction per (pseudo-)time step: system/controlDict says when to stop.\n"
                 "stressAnalysis\n{\n    compactNormalStress yes;\n    nCorrectors     1;\n    D               " +
                 number_text(kSolverTolerance) + ";\n}\n");
  // Each step's output in its log; a failing step says so and stops.
  auto step = [](const std::string& command, const std::string& log) {
    return command + " > " + log + " 2>&1 || { echo \"" + command + " failed: see " + log + "\"; exit 1; }\n";
  };
  std::string solve;
  for (const std::string& word : solver_command(o)) solve += (solve.empty() ? "" : " ") + word;
  if (o.processes > 1) {
    write_decompose_dict(dir, m, o);
    solve = "if [ \"$(id -u)\" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi\n" +
            step("decomposePar -force", "log.decomposePar") + step(solve, "log.solidDisplacementFoam") +
            step("reconstructPar -latestTime", "log.reconstructPar");
  } else {
    solve = step(solve, "log.solidDisplacementFoam");
  }
  write_text(dir / "Allrun",
             "#!/bin/sh\n# Checks the mesh and solves; logs in log.*.\ncd \"${0%/*}\" || exit 1\n"
             "export WM_PROJECT_DIR=\"${WM_PROJECT_DIR:-" + std::string(kFoamProjectDir) + "}\"\n"
             "export GLIBC_TUNABLES=\"" + malloc_tunables() + "${GLIBC_TUNABLES:+:$GLIBC_TUNABLES}\"\n" +
             step("checkMesh", "log.checkMesh") + solve);
  std::filesystem::permissions(dir / "Allrun", std::filesystem::perms::owner_exec | std::filesystem::perms::group_exec |
                                                   std::filesystem::perms::others_exec,
                               std::filesystem::perm_options::add);
  write_text(dir / "case.foam", "");
  return pm;
}

}  // namespace grainmesh
