// Randomness is always passed in, seeded from the configuration. These helpers turn the
// engine's raw bits into numbers the same way on every platform (std:: distributions
// are implementation-defined, which would break byte-for-byte reproducibility).
#pragma once

#include <cstdint>
#include <random>

namespace grainmesh {

using Rng = std::mt19937_64;

// Uniform in [0, 1), 53 random bits.
inline double uniform01(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace grainmesh
