// Resident memory a stage of a run needs: this process's peak over the stage (exact, the
// kernel's high-water mark reset at the stage's start) and, for stages that start
// programs (the solver, decomposePar, mpirun's ranks), this process and all it started
// together, sampled ten times a second. What a scheduler's memory request must cover.
#pragma once

#include <memory>

namespace grainmesh {

class StageMemory {
 public:
  // Starts measuring a stage; with `with_children`, the processes this one starts (and
  // theirs) are summed with it while the stage lasts (by a thread sampling /proc; where
  // no thread can be started, this process's peak alone).
  explicit StageMemory(bool with_children = false);
  ~StageMemory();
  StageMemory(const StageMemory&) = delete;
  StageMemory& operator=(const StageMemory&) = delete;

  // The stage's peak resident memory in MiB (ends the sampling; the same on later calls).
  double peak_mib();

 private:
  struct Sampler;
  std::unique_ptr<Sampler> sampler_;
  double peak_ = -1.0;
};

// The memory a stage may still take, in MiB: the machine's available memory (MemAvailable)
// or, when less, what this process's control group (a SLURM job's, a container's: cgroup
// v2 memory.max or v1 memory.limit_in_bytes) or its address-space limit (ulimit -v, less
// what it has mapped) still allows; infinity when none can be read.
double available_memory_mib();

// Resident memory of process `pid` and every process below it, in MiB, now.
double tree_resident_mib(int pid);

}  // namespace grainmesh
