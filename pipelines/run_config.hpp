// The run config's keys: the keys only a run reads, the whole set a run accepts, the
// embedded default, and the resolved config written back (config.ini) and its fingerprint.
// What a run reads from them is its specification (run_plan.hpp).
#pragma once

#include <string>
#include <vector>

#include "pipelines/config.hpp"

namespace grainmesh {

// The keys only a run reads: homogenise.boundary (mixed | periodic), output.pictures, ...
const std::vector<std::string>& run_own_config_keys();

// Every key a run config may use: the stages' keys.
std::vector<std::string> run_config_keys();

// The embedded default config's text.
const char* default_run_config();

// The config as INI text, section by section in order of first appearance; each of
// `notes` a comment line at the top (what the keys left to their defaults meant).
std::string config_ini(const Config& config, const std::vector<std::string>& notes = {});

// A fingerprint of what a resolved run config asks for (16 hex digits): equal for runs
// that give the same results. Keys that change how a run goes but not its results
// (mesh.threads, limits.seconds) are left out.
std::string config_fingerprint(const Config& config);

}  // namespace grainmesh
