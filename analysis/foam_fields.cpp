#include "analysis/foam_fields.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>

#include "common/errors.hpp"
#include "common/text_file.hpp"
#include "export/foam_material.hpp"
#include "export/foam_options.hpp"
#include "export/foam_solver.hpp"

namespace grainmesh {

namespace {

int width_of(const std::string& type) {
  if (type == "scalar") return 1;
  if (type == "vector") return 3;
  if (type == "symmTensor") return 6;
  if (type == "tensor") return 9;
  throw GeometryError("unknown field type " + type);
}

// The values of an entry `uniform V` or `nonuniform List<T> N (V ...)` starting at `at`;
// in a binary file (`format binary;` in its header, as grainmesh and OpenFOAM write them:
// little-endian 64-bit scalars) the list's values are N x width raw doubles.
FieldValues parse_values(const std::filesystem::path& file, const std::string& text, std::size_t at,
                         const std::string& type, std::size_t count) {
  const std::size_t header_end = text.find('}');
  const std::size_t format = text.find("format", 0);
  const bool binary = format < header_end && text.compare(text.find_first_not_of(" \t", format + 6), 6, "binary") == 0;
  FieldValues f;
  f.width = width_of(type);
  const std::size_t end = text.find(';', at);
  const std::size_t uniform = text.find("uniform", at);
  if (uniform == std::string::npos || uniform > end) throw GeometryError(file.string() + ": no values");
  const bool list = uniform >= 3 && text.compare(uniform - 3, 3, "non") == 0;
  // Numbers read in place (strtod), parentheses and white space skipped: a field of a
  // million cells in well under a second.
  const char* p = text.c_str() + uniform + 7;
  bool ok = true;
  auto skip = [&] {
    while (*p == ' ' || *p == '\n' || *p == '\t' || *p == '\r' || *p == '(' || *p == ')') ++p;
  };
  auto read_value = [&](std::vector<double>& out) {
    for (int c = 0; c < f.width; ++c) {
      skip();
      char* end = nullptr;
      const double v = std::strtod(p, &end);
      if (end == p) ok = false;
      p = end;
      out.push_back(v);
    }
  };
  if (list) {
    while (*p == ' ') ++p;
    if (std::strncmp(p, "List<", 5) != 0) throw GeometryError(file.string() + ": unreadable values");
    p = std::strchr(p, '>');
    if (p == nullptr) throw GeometryError(file.string() + ": unreadable values");
    ++p;
    skip();
    char* end = nullptr;
    const unsigned long long n = std::strtoull(p, &end, 10);
    if (end == p || n != count)
      throw GeometryError(file.string() + ": " + std::to_string(n) + " values, the mesh has " + std::to_string(count));
    p = end;
    if (binary) {
      while (*p == ' ' || *p == '\n' || *p == '\r' || *p == '\t') ++p;
      const std::size_t bytes = count * static_cast<std::size_t>(f.width) * sizeof(double);
      const std::size_t offset = static_cast<std::size_t>(p - text.c_str());
      if (*p != '(' || offset + 1 + bytes >= text.size() || text[offset + 1 + bytes] != ')')
        throw GeometryError(file.string() + ": unreadable binary values");
      f.values.resize(count * static_cast<std::size_t>(f.width));
      std::memcpy(f.values.data(), p + 1, bytes);
      return f;
    }
    f.values.reserve(count * static_cast<std::size_t>(f.width));
    for (std::size_t k = 0; k < count && ok; ++k) read_value(f.values);
  } else {
    std::vector<double> one;
    read_value(one);
    for (std::size_t k = 0; k < count; ++k) f.values.insert(f.values.end(), one.begin(), one.end());
  }
  if (!ok) throw GeometryError(file.string() + ": unreadable values");
  return f;
}

}  // namespace

FieldValues read_cell_field(const std::filesystem::path& file, const std::string& type, std::size_t cells) {
  const std::string text = read_text_file(file, "the solver's result");
  const std::size_t at = text.find("internalField");
  if (at == std::string::npos) throw GeometryError(file.string() + ": no cell values");
  return parse_values(file, text, at, type, cells);
}

FieldValues read_patch_field(const std::filesystem::path& file, const std::string& type, const std::string& patch,
                             std::size_t faces) {
  const std::string text = read_text_file(file, "the solver's result");
  const std::size_t boundary = text.find("boundaryField");
  const std::size_t at = boundary == std::string::npos ? boundary : text.find("\n    " + patch + "\n", boundary);
  if (at == std::string::npos) throw GeometryError(file.string() + ": no patch " + patch);
  const std::size_t value = text.find("value", at), close = text.find('}', at);
  if (value == std::string::npos || value > close) throw GeometryError(file.string() + ": patch " + patch + " has no values");
  return parse_values(file, text, value, type, faces);
}

CaseFields read_case_fields(const std::filesystem::path& result_dir, std::size_t cells) {
  return {read_cell_field(result_dir / "D", "vector", cells), read_cell_field(result_dir / kStressField, "symmTensor", cells)};
}

CaseFields read_case_fields(const std::filesystem::path& result_dir, const std::vector<FoamPhase>& phases,
                            const std::vector<int>& cell_phase, const FoamOptions& o) {
  const std::size_t cells = cell_phase.size();
  CaseFields f = read_case_fields(result_dir, cells);
  if (o.delta_T == 0.0) return f;
  const std::vector<double> thermal = thermal_stress(phases, cell_phase, o);
  for (std::size_t k = 0; k < cells; ++k)
    for (const int diagonal : {0, 3, 5}) f.stress.values[6 * k + static_cast<std::size_t>(diagonal)] -= thermal[k];
  return f;
}

FieldValues superposed(const std::vector<std::pair<double, const FieldValues*>>& terms) {
  FieldValues out{.width = terms.front().second->width, .values = std::vector<double>(terms.front().second->values.size(), 0.0)};
  for (const auto& [weight, field] : terms)
    for (std::size_t i = 0; i < out.values.size(); ++i) out.values[i] += weight * field->values[i];
  return out;
}

CaseFields superposed(const std::vector<std::pair<double, const CaseFields*>>& terms) {
  CaseFields out;
  for (FieldValues CaseFields::*field : {&CaseFields::displacement, &CaseFields::stress}) {
    std::vector<std::pair<double, const FieldValues*>> parts;
    for (const auto& [weight, fields] : terms) parts.push_back({weight, &(fields->*field)});
    out.*field = superposed(parts);
  }
  return out;
}

std::vector<StressState> stress_states(const CaseFields& f, bool plane_stress) {
  std::vector<StressState> out(f.stress.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double* s = f.stress[k];  // OpenFOAM's order: xx xy xz yy yz zz
    out[k] = {.xx = s[0], .yy = s[3], .zz = plane_stress ? 0.0 : s[5], .xy = s[1]};
  }
  return out;
}

std::vector<double> displacement_length(const CaseFields& f) {
  std::vector<double> out(f.displacement.size());
  for (std::size_t k = 0; k < out.size(); ++k)
    out[k] = std::hypot(f.displacement[k][0], f.displacement[k][1], f.displacement[k][2]);
  return out;
}

namespace {

// The case's time directories (names that are numbers) with their times.
std::vector<std::pair<double, std::filesystem::path>> time_dirs(const std::filesystem::path& case_dir) {
  std::vector<std::pair<double, std::filesystem::path>> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(case_dir, ec)) {
    if (!entry.is_directory()) continue;
    const std::string name = entry.path().filename().string();
    char* end = nullptr;
    const double t = std::strtod(name.c_str(), &end);
    if (end != name.c_str() && *end == '\0') out.emplace_back(t, entry.path());
  }
  return out;
}

}  // namespace

void remove_times_after(const std::filesystem::path& case_dir, double time) {
  for (const auto& [t, dir] : time_dirs(case_dir))
    if (t > time) std::filesystem::remove_all(dir);
}

std::filesystem::path latest_time_dir(const std::filesystem::path& case_dir) {
  std::filesystem::path best;
  double latest = 0.0;
  for (const auto& [t, dir] : time_dirs(case_dir)) {
    if (!(t > latest)) continue;
    latest = t;
    best = dir;
  }
  if (best.empty()) throw SolveError(case_dir.string() + ": the solver wrote no result (no time directory after 0)");
  return best;
}

}  // namespace grainmesh
