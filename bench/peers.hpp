// Other meshers run as programs, timed and measured the same way as grainmesh: each a
// child process (wall-clock seconds and peak memory from the kernel), each writing its
// mesh, which is read back here and measured with our own quality measures.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/child.hpp"
#include "mesh/tetmesh.hpp"

namespace grainmesh {

struct ProcessRun {
  double seconds = 0.0;    // wall clock, start to exit
  double peak_mib = 0.0;   // the child's peak resident memory
  int exit_code = -1;
  std::string output;      // stdout and stderr
};

// Runs argv with stdout and stderr to `log`, waits, and returns what it cost.
inline ProcessRun run_process(const std::vector<std::string>& argv, const std::filesystem::path& log) {
  std::fflush(nullptr);  // or the child's freopen would write our buffered output again
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    if (!std::freopen(log.c_str(), "w", stdout)) _exit(127);
    dup2(fileno(stdout), fileno(stderr));
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  ProcessRun r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.peak_mib = static_cast<double>(usage.ru_maxrss) / 1024.0;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  r.output = text.str();
  return r;
}

// Reads a Gmsh 2.2 ASCII .msh file: each node to node(id, x, y, z), each element of
// `type` (2 triangle, 4 tetrahedron) with `corners` nodes to element(node ids).
template <typename Node, typename Element>
void read_msh2(const std::filesystem::path& file, int type, int corners, Node node, Element element) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::string line;
  while (std::getline(in, line)) {
    if (line == "$Nodes") {
      long n = 0;
      in >> n;
      for (long k = 0; k < n; ++k) {
        long id;
        double x, y, z;
        in >> id >> x >> y >> z;
        node(id, x, y, z);
      }
    } else if (line == "$Elements") {
      long n = 0;
      in >> n;
      std::getline(in, line);
      for (long k = 0; k < n; ++k) {
        std::getline(in, line);
        std::istringstream e(line);
        long id, t, ntags;
        e >> id >> t >> ntags;
        for (long g = 0; g < ntags; ++g) e >> id;
        if (t != type) continue;
        std::vector<long> ids(corners);
        for (long& v : ids) e >> v;
        element(ids);
      }
    }
  }
}

// The triangles of a Gmsh 2.2 .msh file, points renumbered from 0 and triangles turned
// counter-clockwise.
inline TriMesh read_msh2(const std::filesystem::path& file) {
  TriMesh m;
  std::map<long, int> index;
  read_msh2(
      file, 2, 3,
      [&](long id, double x, double y, double) {
        index[id] = static_cast<int>(m.points.size());
        m.points.push_back({x, y});
      },
      [&](const std::vector<long>& v) {
        std::array<int, 3> t{index.at(v[0]), index.at(v[1]), index.at(v[2])};
        if (signed_area2(m.points[t[0]], m.points[t[1]], m.points[t[2]]) < 0.0) std::swap(t[1], t[2]);
        m.triangles.push_back(t);
      });
  if (m.triangles.empty()) throw std::runtime_error(file.string() + " holds no triangles");
  return m;
}

// The tetrahedra of a Gmsh 2.2 .msh file, points renumbered from 0 and tetrahedra turned
// positive.
inline TetMesh read_msh2_tets(const std::filesystem::path& file) {
  TetMesh m;
  std::map<long, int> index;
  read_msh2(
      file, 4, 4,
      [&](long id, double x, double y, double z) {
        index[id] = static_cast<int>(m.points.size());
        m.points.push_back({x, y, z});
      },
      [&](const std::vector<long>& v) {
        std::array<int, 4> t{index.at(v[0]), index.at(v[1]), index.at(v[2]), index.at(v[3])};
        if (tet_volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) < 0.0) std::swap(t[2], t[3]);
        m.tets.push_back(t);
      });
  if (m.tets.empty()) throw std::runtime_error(file.string() + " holds no tetrahedra");
  return m;
}

// Gmsh's own time for its 2D meshing, from its log ("Done meshing 2D (Wall 12.3s, ...").
inline double gmsh_meshing_seconds(const std::string& log) {
  std::smatch m;
  static const std::regex done(R"(Done meshing 2D \(Wall ([0-9.eE+-]+)s)");
  if (!std::regex_search(log, m, done)) throw std::runtime_error("no 'Done meshing 2D' in Gmsh's log");
  return std::stod(m[1].str());
}

// The Gmsh version, or "" when the program is missing.
inline std::string gmsh_version(const std::filesystem::path& scratch) {
  const ProcessRun r = run_process({"gmsh", "--version"}, scratch / "gmsh-version.log");
  if (r.exit_code != 0) return "";
  std::string v = r.output;
  while (!v.empty() && (v.back() == '\n' || v.back() == ' ')) v.pop_back();
  return v;
}

}  // namespace grainmesh
