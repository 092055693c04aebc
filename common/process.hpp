// Child processes that never outlive the run that started them: killed when it dies
// (even by SIGKILL) and when its time limit passes.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "common/deadline.hpp"

namespace grainmesh {

// To be called first thing in a child just forked from `parent`: the kernel sends the
// child `signal` (SIGKILL; SIGTERM for a child that cleans up after itself) when the
// parent's thread that forked it dies, also across exec. Exits at once if the parent has
// already gone.
void die_with_parent(pid_t parent, int signal = 9);

// Reads what a child has added to its log since the last call (a few times a second);
// true ends the child (SIGKILL).
using LogWatcher = std::function<bool(std::string_view appended)>;

// A child's own time bounds, beside the run's deadline (which they never outlast): its
// whole run, and a stretch in which it writes nothing to its log; seconds, infinity for
// none. A program that hangs on one input (TetGen on a few surfaces) is stopped at its
// budget, scaled by the caller to what the input asks of it, long before limits.seconds.
struct ChildBudget {
  double seconds = std::numeric_limits<double>::infinity();
  double idle_seconds = std::numeric_limits<double>::infinity();
};
// What run_child returns for a child it stopped at its budget.
inline constexpr int kChildOverBudget = -1;

// Runs `argv` (looked up in PATH) in directory `dir`, stdout and stderr into `log`, and
// waits for it; `environment` (NAME=value entries) is added to this process's environment
// for it, replacing variables of the same name; `watch`, when given, follows the log as it
// grows. Kills it when `deadline` passes and throws TimeLimitError saying `what` was
// running; kills it when `budget` runs out and returns kChildOverBudget. Otherwise returns
// its exit code (128 + the signal when a signal ended it; 127 when it could not be started).
// The child is registered for interrupts (interrupt.hpp): Ctrl-C kills it before the
// temporary files it writes are removed.
int run_child(const std::vector<std::string>& argv, const std::filesystem::path& dir,
              const std::filesystem::path& log, const Deadline& deadline, const std::string& what,
              const std::vector<std::string>& environment = {}, const LogWatcher& watch = {},
              const ChildBudget& budget = {});

}  // namespace grainmesh
