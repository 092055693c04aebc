// `grainmesh run [CONFIG] -o OUT`: tessellate, mesh and export in one process, from one
// config (or the embedded default, data/default.ini). Writes OUT/tessellation.json,
// tessellation.png, mesh.vtu, mesh.json, mesh.png, case/ (the OpenFOAM case), config.ini
// (the resolved config, which repeats the run exactly) and report.json, last; with
// --solve the case is solved and homogenised too.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "export/foam.hpp"
#include "pipelines/config.hpp"

namespace grainmesh {

// The keys only a run reads: homogenise.boundary (mixed | periodic), output.pictures.
const std::vector<std::string>& run_own_config_keys();

// Which pictures a run draws (output.pictures): none (no PNG, and no results.vtu: what a
// sweep wants); basic (tessellation.png, mesh.png and, solved, stress_xx.png and
// results.vtu); all (also mesh_detail.png, stress_yy.png, stress_xy.png and
// displacement.png), the default. true and false are all and none.
enum class Pictures { none, basic, all };
Pictures read_pictures(const Config& config);

// The export's options for a run: with homogenise.boundary = periodic the case is cyclic
// (refused, naming the key, on a cell that is not periodic or with a traction or
// uniaxial load).
FoamOptions read_run_foam_options(const Config& config);

// Every key a run config may use: the stages' keys.
std::vector<std::string> run_config_keys();

// The embedded default config's text.
const char* default_run_config();

// The config as INI text, section by section in order of first appearance.
std::string config_ini(const Config& config);

// With `solve`, also runs solidDisplacementFoam on the case and homogenises (report.json
// "effective"); a run that does not converge fails.
// A terminal shows the stage and the meshing's progress on stderr unless `quiet`; the
// summary goes to stdout when `summary`.
void run_run_command(const Config& config, const std::filesystem::path& out, bool solve = false, bool quiet = false,
                     bool summary = true);

// A fingerprint of what a resolved run config asks for (16 hex digits): equal for runs
// that give the same results. Keys that change how a run goes but not its results
// (mesh.threads, limits.seconds) are left out.
std::string config_fingerprint(const Config& config);

// Checks a run config's keys and the values that can be checked before tessellating (all
// but the mesh keys that depend on the tessellation). Throws ConfigError naming the key.
void check_run_config(const Config& config);

}  // namespace grainmesh
