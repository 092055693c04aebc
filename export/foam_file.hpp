// OpenFOAM's file formats as the export writes them: one file (header, ASCII or binary
// lists), numbers as the shortest text that reads back the same, dictionaries, and the
// volScalarFields of a case. For export/'s own files.
#pragma once

#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "common/geometry.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

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

// The boundary entry of a field for a patch whose type constrains it (symmetryPlane,
// empty, cyclic); empty for the others.
std::string constraint_entry(const PolyMesh::Patch& p);

// A volScalarField in `file`: nonuniform `values` (one per cell), or one value everywhere;
// each patch its constraint type, or zeroGradient.
void write_scalar_field(const std::filesystem::path& file, const std::string& object, const std::string& dimensions,
                        const std::vector<double>& values, const PolyMesh& pm, bool binary);
void write_uniform_scalar_field(const std::filesystem::path& file, const std::string& object,
                                const std::string& dimensions, double value, const PolyMesh& pm);

// The header of an ASCII dictionary at `location` (constant, system) named `object`.
std::string dictionary_header(const std::string& location, const std::string& object);

// Writes `text` as the whole of `file`; IoError when it cannot.
void write_text(const std::filesystem::path& file, const std::string& text);

}  // namespace grainmesh
