// The run config: the keys only a run reads, the whole set a run accepts, what it reads
// from them before any work, and the resolved config written back (config.ini) and its
// fingerprint.
#pragma once

#include <string>
#include <vector>

#include "analysis/homogenise.hpp"
#include "export/foam_options.hpp"
#include "pipelines/config.hpp"
#include "pipelines/report.hpp"

namespace grainmesh {

// The keys only a run reads: homogenise.boundary (mixed | periodic), output.pictures.
const std::vector<std::string>& run_own_config_keys();

// Which pictures a run draws (output.pictures): none (no PNG, and no results.vtu: what a
// sweep wants); basic (tessellation.png, mesh.png and, solved, stress_xx.png and
// results.vtu); all (also mesh_detail.png, stress_yy.png, stress_xy.png and
// displacement.png), the default. true and false are all and none.
enum class Pictures { none, basic, all };
Pictures read_pictures(const Config& config);

// What a solved run keeps of its cases (output.cases): keep (the default: every case, as
// solved), or answers (its report, results.vtu and pictures; the case directories
// dropped once solved: a sweep of hundreds of runs keeps megabytes, not gigabytes).
// answers needs --solve (refused otherwise, naming the key). Returns whether the cases
// are kept.
bool read_keep_cases(const Config& config, bool solve);
// Drops the case directories `cases` from a solved run's staging directory `dir` and
// says so in `report` (cases: dropped).
void drop_cases(const std::filesystem::path& dir, const std::vector<std::string>& cases, Json& report);

// solve.processes (default 1; 1 to 1024), and the periodic cell homogenise.boundary =
// periodic needs (domain.periodic): 2D and 3D runs read them alike.
int read_solve_processes(const Config& config);
void check_periodic_cell(const Config& config);
// load.delta_T (K, default 0): finite; when not zero, every phase's alpha given (>= 0)
// and homogenise.boundary = periodic. 2D and 3D runs read it alike.
double read_delta_T(const Config& config);

// The export's options for a run: with homogenise.boundary = periodic the case is cyclic
// (refused, naming the key, on a cell that is not periodic or with a traction or
// uniaxial load).
FoamOptions read_run_foam_options(const Config& config);

// Every key a run config may use: the stages' keys.
std::vector<std::string> run_config_keys();

// The embedded default config's text.
const char* default_run_config();

// The config as INI text, section by section in order of first appearance; each of
// `notes` a comment line at the top (what the keys left to their defaults meant).
std::string config_ini(const Config& config, const std::vector<std::string>& notes = {});

// How the cell is loaded and homogenised (homogenise.boundary): mixed, the default, or
// periodic.
Boundary read_boundary(const Config& config);

// A fingerprint of what a resolved run config asks for (16 hex digits): equal for runs
// that give the same results. Keys that change how a run goes but not its results
// (mesh.threads, limits.seconds) are left out.
std::string config_fingerprint(const Config& config);

// Checks a run config's keys and the values that can be checked before tessellating (all
// but the mesh keys that depend on the tessellation). Throws ConfigError naming the key.
void check_run_config(const Config& config);

// The case options of a 3D run: export.cells is polyhedra (the tetrahedra's dual, the
// default: its solves converge) or tetrahedra; periodic homogenisation makes the case
// cyclic. Throws ConfigError naming the key.
FoamOptions read_foam_options_3d(const Config& config);
// Checks a 3D run config's keys (the 2D-only ones refused, each saying why) and the values
// that can be checked before tessellating. Throws ConfigError naming the key.
void check_run_3d_config(const Config& config);

}  // namespace grainmesh
