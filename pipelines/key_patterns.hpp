// Known config keys as patterns ("phase.*.fraction": a part "*" stands for any one name):
// whether a key is one, and which known key a misspelt one most likely meant.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace grainmesh {

// Whether `key` matches the known key `pattern`: their dot-separated parts agree, "*"
// matching any one.
bool key_matches(std::string_view pattern, std::string_view key);

// The known key nearest `key` when it is a slip away (a letter or two: US spelling, a
// typo), a "*" part taken as the key's own; empty otherwise.
std::string nearest_key(const std::string& key, const std::vector<std::string>& known);

// What an unknown key's error adds: " (did you mean KEY?)" for a slip, else " (known here:
// KEYS)" when its section has known keys, else nothing.
std::string unknown_key_hint(const std::string& key, const std::vector<std::string>& known);

}  // namespace grainmesh
