// Benchmark runs in child processes, so that each run's peak memory is its own.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
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

// The median run by "seconds" of `runs` children, with the largest peak memory of all.
template <typename F>
Json median_in_children(int runs, F&& measure) {
  std::vector<Json> samples;
  for (int i = 0; i < runs; ++i) {
    samples.push_back(measure_in_child(measure));
    if (samples.back().contains("error")) return samples.back();
  }
  std::sort(samples.begin(), samples.end(),
            [](const Json& a, const Json& b) { return a["seconds"].get<double>() < b["seconds"].get<double>(); });
  Json row = samples[static_cast<std::size_t>(runs / 2)];
  double peak = 0.0;
  for (const Json& s : samples) peak = std::max(peak, s["peak_memory_mib"].get<double>());
  row["peak_memory_mib"] = peak;
  row["runs"] = runs;
  return row;
}

// Writes `file` with the benchmark's name, this machine, how it was timed, and the cases.
inline void write_results(const std::filesystem::path& file, const std::string& benchmark, const std::string& timing,
                          const Json& cases) {
  char host[256] = "unknown";
  gethostname(host, sizeof host);
  const Json doc{{"benchmark", benchmark},
                 {"machine", {{"cores", sysconf(_SC_NPROCESSORS_ONLN)}, {"host", host}}},
                 {"timing", timing},
                 {"cases", cases}};
  std::ofstream(file) << doc.dump(2) << "\n";
  std::printf("wrote %s\n", file.string().c_str());
}

}  // namespace grainmesh
