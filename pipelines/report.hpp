// Pieces every report.json shares.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/deadline.hpp"
#include "mesh/quality.hpp"
#include "pipelines/output_dir.hpp"

namespace grainmesh {

// JSON objects keep their keys in insertion order, so reports read top-down.
using Json = nlohmann::ordered_json;

// The version of report.json's layout this grainmesh writes ("schema", second), described
// by docs/report.schema.json. Reports without one were written before it (schema 1).
inline constexpr int kReportSchema = 2;

// Peak resident memory of this process so far, in MiB.
double peak_memory_mib();

// The quality measures under their report names (q_min, q_mean, min_angle_deg, ...).
void add_quality(Json& report, const MeshQuality& q);

// "time_limit_seconds": the run's wall-clock guard (limits.seconds), or "none".
void add_time_limit(Json& report, const Deadline& deadline);

// Pretty-printed JSON, written through a temporary file. Throws IoError.
void write_json(const std::filesystem::path& file, const Json& json);
// A JSON file read; IoError naming it when it cannot be read or parsed.
Json read_json(const std::filesystem::path& file);

// What a command found doubtful but not wrong (a poor mesh, a missed target, a bound
// crossed): each printed to stderr at once, one line "grainmesh: warning: ...", and kept
// for report.json's "warnings".
class Warnings {
 public:
  // `echo`: each warning also on stderr as it is added (a run's); without, only kept.
  Warnings() = default;
  explicit Warnings(bool echo) : echo_(echo) {}
  void add(const std::string& warning);
  const std::vector<std::string>& all() const { return lines_; }

 private:
  bool echo_ = true;
  std::vector<std::string> lines_;
};

// Writes `report` as the staged output's report.json, last: with "command" (the output's
// kind) and "schema" first, then "warnings" and "files" (every entry of the directory) at the end.
// Returns the report as written.
Json write_report(const StagedOutput& out, Json report, const Warnings& warnings = {});

// How a stage command (tessellate, mesh) ends: `report` with its time limit and the peak
// memory written last into `staged`, the output committed; returns the report as written.
Json finish_stage(StagedOutput& staged, Json report, const Deadline& deadline, const Warnings& warnings);
// "  wrote OUT/{entries}" on stdout, with the pictures' section height when `report` has one.
void print_written(const std::filesystem::path& out, const Json& report);

}  // namespace grainmesh
