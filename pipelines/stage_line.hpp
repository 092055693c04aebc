// The stage of a long command on one line of a terminal, rewritten in place.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace grainmesh {

using Clock = std::chrono::steady_clock;

inline double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The stage on one line of a terminal, rewritten in place (at most ten times a second);
// nothing when not shown.
class StageLine {
 public:
  StageLine(bool show, Clock::time_point start) : show_(show), start_(start), last_(start - std::chrono::seconds(1)) {}
  bool shown() const { return show_; }
  void show(const std::string& what, bool force = true) const {
    if (!show_) return;
    const auto now = Clock::now();
    if (!force && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    std::fprintf(stderr, "\r\033[Kgrainmesh run: %s (%.1f s)", what.c_str(), since(start_));
    std::fflush(stderr);
  }
  void end() const {
    if (show_) std::fprintf(stderr, "\r\033[K");
  }

 private:
  bool show_;
  Clock::time_point start_;
  mutable Clock::time_point last_;  // when the line was last rewritten
};

}  // namespace grainmesh
