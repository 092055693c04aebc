#include "analysis/check_mesh.hpp"

#include <cstdlib>
#include <sstream>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/process.hpp"
#include "common/text_file.hpp"
#include "export/foam_solver.hpp"

namespace grainmesh {

MeshCheck read_mesh_check(const std::string& log) {
  MeshCheck c;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    const std::string text = trimmed(line);
    if (text.rfind("***", 0) == 0) c.failures.push_back(text.substr(3));
    if (text.rfind("Failed ", 0) == 0 && text.find("mesh check") != std::string::npos)
      c.failed_checks = std::atoi(text.c_str() + 7);
  }
  if (c.failed_checks == 0 && !c.failures.empty()) c.failed_checks = static_cast<int>(c.failures.size());
  return c;
}

MeshCheck check_mesh(const std::filesystem::path& case_dir, const Deadline& deadline) {
  std::uintmax_t bytes = 0;
  std::error_code ec;
  for (const auto& f : std::filesystem::directory_iterator(case_dir / "constant" / "polyMesh", ec))
    if (f.is_regular_file(ec)) bytes += f.file_size(ec);
  const std::filesystem::path log = case_dir / "log.checkMesh";
  const int status = run_child({"checkMesh"}, case_dir, log, deadline, "checkMesh", foam_environment(), {},
                               {.seconds = 120.0 + 20.0 * static_cast<double>(bytes) / 1e6});
  if (status == 127) throw IoError("checkMesh is not installed (Debian package openfoam; scripts/install-deps.sh)");
  if (status == kChildOverBudget) throw IoError((case_dir / "log.checkMesh").string() + ": checkMesh did not finish in its time budget");
  MeshCheck c = read_mesh_check(read_text_file(log, "checkMesh's log"));
  c.log = log.filename().string();
  if (status != 0 && c.failed_checks == 0)
    throw IoError(log.string() + ": checkMesh failed (exit code " + std::to_string(status) + ")");
  return c;
}

std::string mesh_check_warning(const MeshCheck& c, const std::string& case_name) {
  if (c.failed_checks == 0) return {};
  std::string what;
  for (const std::string& f : c.failures) what += (what.empty() ? "" : "; ") + f;
  return "checkMesh: failed " + std::to_string(c.failed_checks) + " mesh check" + (c.failed_checks > 1 ? "s" : "") +
         " in " + case_name + (what.empty() ? "" : " (" + what + ")") + "; see " + case_name + "/" + c.log +
         " (the solve ran; its answer may be less accurate where the check failed)";
}

}  // namespace grainmesh
