// Pieces every report.json shares.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/deadline.hpp"
#include "mesh/quality.hpp"

namespace grainmesh {

// JSON objects keep their keys in insertion order, so reports read top-down.
using Json = nlohmann::ordered_json;

// Peak resident memory of this process so far, in MiB.
double peak_memory_mib();

// The quality measures under their report names (q_min, q_mean, min_angle_deg, ...).
void add_quality(Json& report, const MeshQuality& q);

// "time_limit_seconds": the run's wall-clock guard (limits.seconds), or "none".
void add_time_limit(Json& report, const Deadline& deadline);

// Pretty-printed JSON, written through a temporary file. Throws IoError.
void write_json(const std::filesystem::path& file, const Json& json);

}  // namespace grainmesh
