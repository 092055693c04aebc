// Reading a run's report.json back (sweep --collect, converge, a sweep's resume): the
// report in this grainmesh's schema (kReportSchema), an older one brought up to it.
#pragma once

#include <filesystem>

#include "pipelines/report.hpp"

namespace grainmesh {

// `file` parsed, in schema kReportSchema. A report without "schema" (schema 1: 2D reports
// with phases at the top, expansion a11 ..., the stiffness as solved with C21, C61, C62
// and load cases in an array; 3D reports with phases in statistics, load cases by name)
// is upgraded: the same numbers under schema 2's names, each stiffness its symmetric part.
// Throws IoError naming the file when it is no JSON, and naming the version when it is a
// schema this grainmesh does not know (a newer one).
Json read_report(const std::filesystem::path& file);

// A schema-1 report as schema 2 writes it (what read_report does to one).
Json upgrade_report(Json report);

}  // namespace grainmesh
