// Every config key in one table: which commands read it, its default and what it means.
// The commands' key lists, which their config readers check against, are drawn from it,
// and `grainmesh keys` prints it (key_reference.hpp), so the reference cannot drift from
// what is read.
#pragma once

#include <string>
#include <vector>

namespace grainmesh {

// The commands a key belongs to (bits). `run` takes the keys of tessellate, mesh and
// export and its own; sweep takes a run's and its own.
enum KeyCommands : unsigned {
  kTessellateKey = 1u << 0,
  kMeshKey = 1u << 1,
  kExportKey = 1u << 2,
  kRunKey = 1u << 3,  // read by run alone (solve, homogenisation, what it keeps)
  kDomainKey = 1u << 4,
  kSweepKey = 1u << 5,
};

struct ConfigKey {
  const char* key;          // "section.name"; "*" stands for any one name (a phase's)
  unsigned commands;        // KeyCommands
  const char* default_text; // what applies when the key is not given ("-": nothing, or required)
  const char* meaning;       // one line: what `grainmesh keys` prints
  const char* details = nullptr;  // markdown, for the reference (docs/keys.md): more than the line says
};

// The table, in the order the reference lists it.
const std::vector<ConfigKey>& config_key_table();

// The keys of the commands in `commands` (any of the bits), in the table's order.
std::vector<std::string> keys_of(unsigned commands);

// The keys of the tessellate and mesh stages (keys_of(kTessellateKey), of kMeshKey), kept.
const std::vector<std::string>& tessellate_config_keys();
const std::vector<std::string>& mesh_config_keys();

}  // namespace grainmesh
