// Ctrl-C, SIGTERM and SIGHUP: a run stops at once and leaves nothing behind. main() calls
// install_interrupt_handling() before any other thread starts: the three signals are
// blocked in every thread, and one thread of its own waits for them. When one comes, that
// thread stops the registered children (OpenFOAM's programs at once; TetGen's helpers die with the process, a sweep's
// runs given a moment to clean up after themselves), holds the process's other threads
// still, removes the registered temporary paths (staging directories)
// while nothing can write into them, prints one line - "grainmesh:
// interrupted; " and the run's own words - and exits with 128 + the signal.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>

namespace grainmesh {

// Blocks SIGINT, SIGTERM and SIGHUP in this thread (and so in the threads it starts) and
// starts the thread that waits for them. In a process just forked from one that had
// called it, call it again: the parent's registrations are the parent's, and are forgotten.
// `message` is what the line printed on an interrupt says (set_interrupt_message), in
// place from the first moment a signal can be handled.
void install_interrupt_handling(std::string message = "nothing was written");

// What the line printed on an interrupt says after "grainmesh: interrupted; " (by default
// "nothing was written").
void set_interrupt_message(std::string message);

// Whether an interrupt is being handled; the process is about to exit.
bool interrupted();
// Never returns once an interrupt is being handled (the handling thread ends the process):
// for a thread about to report an error that the interrupt caused (a child it killed).
void wait_if_interrupted();

// A path removed when the run is interrupted, for as long as the object lives.
class TemporaryPath {
 public:
  TemporaryPath() = default;
  explicit TemporaryPath(std::filesystem::path path);
  ~TemporaryPath();
  TemporaryPath(TemporaryPath&& other) noexcept;
  TemporaryPath& operator=(TemporaryPath&& other) noexcept;
  TemporaryPath(const TemporaryPath&) = delete;
  TemporaryPath& operator=(const TemporaryPath&) = delete;
  // No longer removed on an interrupt (it has become the output).
  void release();

 private:
  int id_ = -1;
};

// A child process, forked and registered in one step (an interrupt waits for the step to
// end, so it never misses a child just started), stopped when the run is interrupted for
// as long as the object lives: with SIGKILL, or (`graceful`: mpirun, which must take its
// ranks with it, and a sweep's runs, which remove their own staging directories) with
// SIGTERM and, after a few seconds, SIGKILL. In the child pid() is 0 and the object holds
// nothing: the child must exec, or call install_interrupt_handling before it registers
// anything. pid() is -1 when fork failed.
class RegisteredChild {
 public:
  explicit RegisteredChild(bool graceful = false);
  ~RegisteredChild();
  RegisteredChild(const RegisteredChild&) = delete;
  RegisteredChild& operator=(const RegisteredChild&) = delete;
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  int id_ = -1;
};

// Stops child `pid` (this process's) and reaps it: SIGKILL, or when `graceful` SIGTERM
// first and SIGKILL after `grace_seconds`. Returns its wait status.
int stop_child(pid_t pid, bool graceful, double grace_seconds = 5.0);

}  // namespace grainmesh
