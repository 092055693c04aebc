// The config key reference printed from the one key table (config_keys.hpp): a line per
// key for `grainmesh keys` and --help, markdown for docs/keys.md.
#pragma once

#include <string>

namespace grainmesh {

// The reference as text: for the commands in `commands`, each key with its default and
// meaning, a line each, grouped by section.
std::string key_reference(unsigned commands);

// The whole reference as markdown (docs/keys.md is this, and a test holds it so): a table
// per section, each key with the commands that read it, its default, its meaning and
// details.
std::string key_reference_markdown();

}  // namespace grainmesh
