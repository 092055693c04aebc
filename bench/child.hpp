// Benchmark runs in child processes, so that each run's peak memory is its own.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "mesh/quality.hpp"
#include "mesh/trimesh.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace grainmesh {

using Json = nlohmann::ordered_json;

// Runs `measure` (returning a Json with "seconds") in a forked child; adds the child's
// peak resident memory as "peak_memory_mib". A thrown error comes back as {"error"}.
template <typename F>
Json measure_in_child(F&& measure) {
  int fd[2];
  if (pipe(fd) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    std::string out;
    try {
      out = measure().dump();
    } catch (const std::exception& e) {
      out = Json{{"error", e.what()}}.dump();
    }
    const ssize_t written = write(fd[1], out.data(), out.size());
    _exit(written == static_cast<ssize_t>(out.size()) ? 0 : 1);
  }
  close(fd[1]);
  std::string text;
  char buf[4096];
  for (ssize_t n; (n = read(fd[0], buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
  close(fd[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  Json j = Json::parse(text);
  j["peak_memory_mib"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
  return j;
}

// The median sample by "seconds" (and by "process_seconds" too, where samples have it),
// with the largest peak memory of all and the number of samples as "runs".
inline Json median_of(std::vector<Json> samples) {
  std::sort(samples.begin(), samples.end(),
            [](const Json& a, const Json& b) { return a["seconds"].get<double>() < b["seconds"].get<double>(); });
  Json row = samples[samples.size() / 2];
  std::vector<double> process;
  double peak = 0.0;
  for (const Json& s : samples) {
    if (s.contains("process_seconds")) process.push_back(s["process_seconds"].get<double>());
    peak = std::max(peak, s["peak_memory_mib"].get<double>());
  }
  if (process.size() == samples.size()) {
    std::sort(process.begin(), process.end());
    row["process_seconds"] = process[process.size() / 2];
  }
  row["peak_memory_mib"] = peak;
  row["runs"] = samples.size();
  return row;
}

// The median of `runs` children (see median_of); the first error, if any.
template <typename F>
Json median_in_children(int runs, F&& measure) {
  std::vector<Json> samples;
  for (int i = 0; i < runs; ++i) {
    samples.push_back(measure_in_child(measure));
    if (samples.back().contains("error")) return samples.back();
  }
  return median_of(std::move(samples));
}

inline Json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return Json::parse(in);
}

// Runs `binary` (the grainmesh command) with `args`, its output into `log`; throws with
// that output when it fails.
inline void run_command(const std::string& binary, const std::string& args, const std::filesystem::path& log) {
  const std::string command = binary + " " + args + " > " + log.string() + " 2>&1";
  if (std::system(command.c_str()) != 0) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    throw std::runtime_error(binary + " " + args + " failed: " + text.str());
  }
}

// Points, triangles and the quality measures every table reports.
inline Json mesh_measures(const TriMesh& m, const MeshQuality& q) {
  return {{"points", m.points.size()},  {"triangles", m.triangles.size()}, {"q_min", q.q_min},
          {"q_mean", q.q_mean},         {"q_below_0_5", q.q_below_half},  {"min_angle_deg", q.min_angle_deg}};
}
inline Json mesh_measures(const TriMesh& m) { return mesh_measures(m, measure_quality(m)); }

// This machine: processor, cores, memory, system and compiler.
inline Json machine() {
  auto first_line_with = [](const char* file, const std::string& key) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);)
      if (line.rfind(key, 0) == 0) {
        const auto colon = line.find_first_of(":=");
        std::string v = colon == std::string::npos ? line : line.substr(colon + 1);
        v.erase(0, v.find_first_not_of(" \t\""));
        while (!v.empty() && (v.back() == '"' || v.back() == ' ')) v.pop_back();
        return v;
      }
    return std::string("unknown");
  };
  return {{"cpu", first_line_with("/proc/cpuinfo", "model name")},
          {"cores", sysconf(_SC_NPROCESSORS_ONLN)},
          {"memory", first_line_with("/proc/meminfo", "MemTotal")},
          {"system", first_line_with("/etc/os-release", "PRETTY_NAME")},
          {"compiler", "GCC " __VERSION__}};
}

// Records one benchmark's cases, how they were timed and this machine in `file` (a JSON
// document shared by every benchmark: each replaces only its own entry).
inline void write_results(const std::filesystem::path& file, const std::string& benchmark, const std::string& timing,
                          const Json& cases) {
  Json doc = Json::object();
  if (std::ifstream in(file); in) {
    doc = Json::parse(in, nullptr, false);
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("benchmarks")) doc = Json::object();
  }
  doc["machine"] = machine();
  doc["benchmarks"][benchmark] = Json{{"timing", timing}, {"cases", cases}};
  std::ofstream(file) << doc.dump(2) << "\n";
  std::printf("wrote %s (\"%s\")\n", file.string().c_str(), benchmark.c_str());
}

}  // namespace grainmesh
