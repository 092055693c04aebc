// What checkMesh's log says, for the tests that run it on our cases.
#pragma once

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "export/foam_material.hpp"
#include "helpers.hpp"

namespace grainmesh::test {

// Cell counts per zone, as checkMesh reports them under "Checking basic cellZone addressing".
inline std::map<std::string, int> zone_cells(const std::string& log) {
  std::map<std::string, int> zones;
  const auto start = log.find("Checking basic cellZone addressing");
  if (start == std::string::npos) return zones;
  std::istringstream in(log.substr(start));
  std::string line;
  std::getline(in, line);
  std::getline(in, line);  // the column titles
  const std::regex row(R"(^\s+(\S+)\s+(\d+)\s+\d+\s+\S+)");
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) break;
    zones[m[1]] = std::stoi(m[2]);
  }
  return zones;
}


// checkMesh on the case: it exits 0, says "Mesh OK.", and has a cellZone per phase
// holding that phase's cells (`phase`: each cell's, in the mesh's order).
inline std::map<std::string, int> check_mesh_ok(const std::filesystem::path& case_dir,
                                                const std::vector<FoamPhase>& phases, const std::vector<int>& phase) {
  const auto r = run_openfoam(case_dir, "checkMesh");
  std::string failed;  // checkMesh marks each failed check with ***
  for (std::size_t at = r.out.find("***"); at != std::string::npos; at = r.out.find("***", at + 3))
    failed += r.out.substr(at, r.out.find('\n', at) - at) + "\n";
  INFO(failed + r.out.substr(r.out.size() > 2000 ? r.out.size() - 2000 : 0));
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("Mesh OK.") != std::string::npos);
  const auto zones = zone_cells(r.out);
  for (std::size_t p = 0; p < phases.size(); ++p) {
    REQUIRE(zones.count(phases[p].name) == 1);
    CHECK(zones.at(phases[p].name) == std::count(phase.begin(), phase.end(), static_cast<int>(p)));
  }
  return zones;
}

}  // namespace grainmesh::test
