// OpenFOAM's own judgement of a case's mesh: checkMesh run on it, its failed checks
// turned into warnings, so that a case whose log says "Failed 1 mesh checks" is never
// reported as if nothing were amiss.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/deadline.hpp"

namespace grainmesh {

struct MeshCheck {
  int failed_checks = 0;             // checkMesh's "Failed N mesh checks."
  std::vector<std::string> failures; // its "***" lines: each failed check, with its counts
  std::string log;                   // the log's name in the case (log.checkMesh)
};

// Runs checkMesh in `case_dir` (log in log.checkMesh beside it) under a budget scaled to
// the mesh. Throws IoError when checkMesh is not installed or cannot finish, and
// TimeLimitError when the deadline passes.
MeshCheck check_mesh(const std::filesystem::path& case_dir, const Deadline& deadline);

// checkMesh's verdict in the text of its log.
MeshCheck read_mesh_check(const std::string& log);

// The warning a failed check makes, naming the case as `case_name`; empty when all passed.
std::string mesh_check_warning(const MeshCheck& check, const std::string& case_name);

}  // namespace grainmesh
