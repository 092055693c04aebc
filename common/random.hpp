// Randomness is always passed in, seeded from the configuration. These helpers turn the
// engine's raw bits into numbers the same way on every platform (std:: distributions
// are implementation-defined, which would break byte-for-byte reproducibility).
#pragma once

#include <cstdint>
#include <random>

namespace grainmesh {

using Rng = std::mt19937_64;

// A seed of its own for item `index` (of group `group`) of a run seeded with `seed`, the
// same whichever thread or shard asks for it: SplitMix64's finaliser over
// seed * phi + group * c + index + 1. Cost: a few multiplications.
inline std::uint64_t derived_seed(std::uint64_t seed, std::uint64_t index, std::uint64_t group = 0) {
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + group * 0xD1B54A32D192ED03ull + index + 1;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Uniform in [0, 1), 53 random bits.
inline double uniform01(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace grainmesh
