#include "pipelines/report.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/text_file.hpp"
#include "pipelines/directory.hpp"
#include "pipelines/output_dir.hpp"

namespace grainmesh {

double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

void add_quality(Json& report, const MeshQuality& q) {
  report["q_min"] = q.q_min;
  report["q_mean"] = q.q_mean;
  report["q_below_0_5"] = q.q_below_half;
  report["min_angle_deg"] = q.min_angle_deg;
  report["max_angle_deg"] = q.max_angle_deg;
  report["max_non_orthogonality_deg"] = q.max_non_orthogonality_deg;
  report["mean_non_orthogonality_deg"] = q.mean_non_orthogonality_deg;
  report["max_skewness"] = q.max_skewness;
}

void write_json(const std::filesystem::path& file, const Json& json) { write_text_file(file, json.dump(2) + "\n"); }

Json read_json(const std::filesystem::path& file) {
  const std::string text = read_text_file(file);
  try {
    return Json::parse(text);
  } catch (const Json::exception& e) {
    throw IoError(file.string() + ": not valid JSON: " + e.what());
  }
}

void Warnings::add(const std::string& warning) {
  if (echo_) std::fprintf(stderr, "grainmesh: warning: %s\n", warning.c_str());
  lines_.push_back(warning);
}

Json write_report(const StagedOutput& out, Json report, const Warnings& warnings) {
  Json ordered{{kReportCommand, out.kind()}, {"schema", kReportSchema}};
  for (auto& [key, value] : report.items())
    if (key != kReportCommand && key != "schema") ordered[key] = std::move(value);
  ordered["warnings"] = warnings.all();
  std::vector<std::string> files = entry_names(out.dir());
  files.push_back("report.json");
  std::sort(files.begin(), files.end());
  ordered[kReportFiles] = files;
  write_json(out.dir() / "report.json", ordered);
  return ordered;
}

void add_time_limit(Json& report, const Deadline& deadline) {
  const double limit = deadline.limit_seconds();
  report["time_limit_seconds"] = std::isfinite(limit) ? Json(limit) : Json("none");
}

Json finish_stage(StagedOutput& staged, Json report, const Deadline& deadline, const Warnings& warnings) {
  add_time_limit(report, deadline);
  report["peak_memory_mib"] = peak_memory_mib();
  Json written = write_report(staged, std::move(report), warnings);
  staged.commit();
  return written;
}

void print_written(const std::filesystem::path& out, const Json& report) {
  const std::string section =
      report.contains("section_z") ? " (section z = " + to_text(report["section_z"].get<double>()) + ")" : "";
  std::printf("  wrote %s/{%s}%s\n", out.string().c_str(), entry_list(out).c_str(), section.c_str());
}

}  // namespace grainmesh
