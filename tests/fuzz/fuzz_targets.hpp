// What the fuzzers check, one function per target, shared by the libFuzzer programs
// (fuzz_*.cpp, clang only) and by the unit test that replays their corpora and every
// input that once failed (tests/fuzz/regressions). Each takes arbitrary bytes. Refusing
// them with the tool's own errors (ConfigError, GeometryError, IoError) is fine; any other
// exception, a crash, a sanitizer report or a broken invariant (FuzzFailure) is a bug.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>

namespace grainmesh::fuzz {

struct FuzzFailure : std::logic_error {
  using std::logic_error::logic_error;
};

// The input as an INI config (text after a line "--set" gives one KEY=VALUE override per
// line), read by every stage's reader: tessellate, mesh (against a small fixed
// tessellation), export and domain; a domain's distance and size functions are evaluated
// on a grid.
void config(std::span<const std::uint8_t> data);

// The input as tessellation.json. A tessellation the reader accepts must be valid; a
// small one is meshed, and the mesh must pass the conformity check.
void tessellation_json(std::span<const std::uint8_t> data);

// The input as polygon rings (raw vertices, or star-shaped rings that are simple by
// construction); a polygon the validator accepts must give, at vertices, edge midpoints,
// points a hair off its edges and a grid, the brute-force distance to its edges, with the
// sign of an exact crossing-number test.
void polygon_distance(std::span<const std::uint8_t> data);

}  // namespace grainmesh::fuzz
