// The only test source compiled with the clone's absolute paths (GRAINMESH_SOURCE_DIR,
// GRAINMESH_BINARY): every other one compiles to the same command in any clone, so ccache
// serves them to a fresh clone.
#include <filesystem>

namespace grainmesh::test {

std::filesystem::path source_dir() { return GRAINMESH_SOURCE_DIR; }
const char* grainmesh_binary() { return GRAINMESH_BINARY; }

}  // namespace grainmesh::test
