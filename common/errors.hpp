// The errors grainmesh reports to its users. Each message names the key, file or value at
// fault, fits on one line, and is printed by main() alone; libraries only throw.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace grainmesh {

// What the line of an error begins with, on stderr (a sweep's runs: in their logs).
inline constexpr std::string_view kErrorPrefix = "grainmesh: error: ";

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A configuration key, command-line option or value is missing, unknown or out of range.
struct ConfigError : Error {
  using Error::Error;
};

// The geometry cannot be meshed as given (empty domain, self-intersecting polygon, ...).
struct GeometryError : Error {
  using Error::Error;
};

// A file or directory could not be read or written.
struct IoError : Error {
  using Error::Error;
};

// The run's time limit passed; the message says where the work stood (see deadline.hpp).
struct TimeLimitError : Error {
  using Error::Error;
};

// The solver failed, diverged, stalled or did not converge.
struct SolveError : Error {
  using Error::Error;
};

// The exit code README.md documents for each error family.
enum ExitCode { kExitOk = 0, kExitInternal = 1, kExitConfig = 2, kExitGeometry = 3, kExitIo = 4, kExitTimeLimit = 5,
                kExitSolve = 6 };
inline int exit_code_of(const std::exception& e) {
  if (dynamic_cast<const ConfigError*>(&e)) return kExitConfig;
  if (dynamic_cast<const GeometryError*>(&e)) return kExitGeometry;
  if (dynamic_cast<const IoError*>(&e)) return kExitIo;
  if (dynamic_cast<const TimeLimitError*>(&e)) return kExitTimeLimit;
  if (dynamic_cast<const SolveError*>(&e)) return kExitSolve;
  return kExitInternal;
}
// Throws the error of the family that exits with `code` (a child's, passed on).
[[noreturn]] inline void throw_error(int code, const std::string& message) {
  switch (code) {
    case kExitConfig: throw ConfigError(message);
    case kExitGeometry: throw GeometryError(message);
    case kExitIo: throw IoError(message);
    case kExitTimeLimit: throw TimeLimitError(message);
    case kExitSolve: throw SolveError(message);
    default: throw Error(message);
  }
}

}  // namespace grainmesh
