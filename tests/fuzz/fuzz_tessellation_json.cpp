// libFuzzer entry point of the tessellation_json target (see fuzz_targets.hpp).
#include "fuzz/fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  grainmesh::fuzz::tessellation_json({data, size});
  return 0;
}
