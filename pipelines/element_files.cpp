#include "pipelines/element_files.hpp"

#include <sstream>

#include "common/format.hpp"
#include "export/gmsh_file.hpp"

namespace grainmesh {

ExportFormats read_export_formats(const Config& c) {
  ExportFormats f;
  if (!c.has("export.format")) return f;
  std::istringstream in(c.text("export.format"));
  for (std::string item; std::getline(in, item, ',');) {
    item = trimmed(item);
    const bool encoding = item == "ascii" || item == "binary";
    if (encoding && f.binary.has_value())
      c.fail("export.format", "names the case's encoding twice (ascii or binary, one of them), got '" +
                                  c.text("export.format") + "'");
    if (encoding) f.binary = item == "binary";
    else if (item == "gmsh") f.gmsh = true;
    else if (item == "abaqus") f.abaqus = true;
    else
      c.fail("export.format", "must be a list of ascii or binary (the OpenFOAM case), gmsh (mesh.msh) and abaqus "
                              "(mesh.inp), got '" + item + "'");
  }
  return f;
}

std::vector<std::string> write_element_files(const std::filesystem::path& dir, const ElementMesh& m,
                                             const ExportFormats& formats, const AbaqusOptions& abaqus) {
  std::vector<std::string> names;
  if (formats.gmsh) {
    write_gmsh(dir / "mesh.msh", m);
    names.push_back("mesh.msh");
  }
  if (formats.abaqus) {
    write_abaqus(dir / "mesh.inp", m, abaqus);
    names.push_back("mesh.inp");
  }
  return names;
}

}  // namespace grainmesh
