#include "export/foam_file.hpp"

#include <charconv>
#include <fstream>

#include "common/errors.hpp"

namespace grainmesh {

std::string constraint_entry(const PolyMesh::Patch& p) {
  if (p.type == "symmetryPlane" || p.type == "empty" || p.type == "cyclic") return "type " + p.type + ";";
  return "";
}

namespace {

// A scalar field's boundary: each patch its constraint type, or zeroGradient.
void write_scalar_boundary(FoamFile& f, const PolyMesh& pm) {
  f.text(";\n\nboundaryField\n{\n");
  for (const PolyMesh::Patch& p : pm.patches) {
    const std::string c = constraint_entry(p);
    f.text("    " + p.name + "\n    {\n        " + (c.empty() ? "type zeroGradient;" : c) + "\n    }\n");
  }
  f.text("}\n").write();
}

}  // namespace

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

}  // namespace grainmesh
