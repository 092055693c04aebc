// The errors grainmesh reports to its users. Each message names the key, file or value at
// fault, fits on one line, and is printed by main() alone; libraries only throw.
#pragma once

#include <stdexcept>
#include <string>

namespace grainmesh {

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

}  // namespace grainmesh
