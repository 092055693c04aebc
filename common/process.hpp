// Child processes that never outlive the run that started them: killed when it dies
// (even by SIGKILL) and when its time limit passes.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "common/deadline.hpp"

namespace grainmesh {

// To be called first thing in a child just forked from `parent`: the kernel sends the
// child SIGKILL when the parent dies, also across exec. Exits at once if the parent has
// already gone.
void die_with_parent(pid_t parent);

// Reads what a child has added to its log since the last call (a few times a second);
// true ends the child (SIGKILL).
using LogWatcher = std::function<bool(std::string_view appended)>;

// Runs `argv` (looked up in PATH) in directory `dir`, stdout and stderr into `log`, and
// waits for it; `environment` (NAME=value entries) is added to this process's environment
// for it, replacing variables of the same name; `watch`, when given, follows the log as it grows. Kills it when
// `deadline` passes and throws TimeLimitError saying `what` was running. Returns its exit
// code (128 + the signal when a signal ended it; 127 when it could not be started).
int run_child(const std::vector<std::string>& argv, const std::filesystem::path& dir,
              const std::filesystem::path& log, const Deadline& deadline, const std::string& what,
              const std::vector<std::string>& environment = {}, const LogWatcher& watch = {});

}  // namespace grainmesh
