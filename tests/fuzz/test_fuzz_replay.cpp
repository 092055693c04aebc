// The fuzz targets' checks on their seeds and on every input that once failed, in every
// build (the fuzzers themselves need clang; see tests/CMakeLists.txt).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "fuzz/fuzz_targets.hpp"
#include "helpers.hpp"

namespace fs = std::filesystem;
using namespace grainmesh;

namespace {

void replay(const std::string& target, const std::vector<fs::path>& seeds,
            const std::function<void(std::span<const std::uint8_t>)>& check) {
  std::vector<fs::path> dirs = seeds;
  dirs.push_back(test::source_dir() / "tests" / "fuzz" / "regressions" / target);
  std::vector<fs::path> files;
  for (const fs::path& dir : dirs)
    for (const fs::path& rel : test::files_under(dir)) files.push_back(dir / rel);
  REQUIRE(!files.empty());
  for (const fs::path& file : files) {
    INFO(file.string());
    const std::string bytes = test::read_file(file);
    CHECK_NOTHROW(check({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}));
  }
}

}  // namespace

TEST_CASE("fuzz replay: config reader on the example configs and past failures", "[fuzz]") {
  replay("config", {test::source_dir() / "data"}, fuzz::config);
}

TEST_CASE("fuzz replay: tessellation.json reader on its seeds and past failures", "[fuzz]") {
  replay("tessellation_json", {test::source_dir() / "tests" / "fuzz" / "seeds" / "tessellation_json"},
         fuzz::tessellation_json);
}

TEST_CASE("fuzz replay: polygon distance on its seeds and past failures", "[fuzz]") {
  replay("polygon_distance", {test::source_dir() / "tests" / "fuzz" / "seeds" / "polygon_distance"},
         fuzz::polygon_distance);
}
