// The grainmesh commands' command lines: each parses its arguments (command_line.hpp),
// runs its command and returns 0 (the exit code of --help too); errors are thrown, for
// main() to print and map to their exit codes (docs/errors.md).
#pragma once

#include <string>
#include <vector>

namespace grainmesh {

int run_main(const std::vector<std::string>& args);
int converge_main(const std::vector<std::string>& args);
int sweep_main(const std::vector<std::string>& args);
int tessellate_main(const std::vector<std::string>& args);
int mesh_main(const std::vector<std::string>& args);
int check_main(const std::vector<std::string>& args);
int export_main(const std::vector<std::string>& args);
int domain_main(const std::vector<std::string>& args);
int keys_main(const std::vector<std::string>& args);

}  // namespace grainmesh
