// Where a config's values came from: its source (a file name, or "default") and the keys
// given with --set. What a stage keeps of its config to name the key at fault in an error
// found after reading it (a phase left without grains, a size too fine for the cell), so
// that no stage reads its config twice.
#pragma once

#include <set>
#include <string>
#include <utility>

#include "common/errors.hpp"

namespace grainmesh {

class ConfigOrigin {
 public:
  ConfigOrigin() = default;
  ConfigOrigin(std::string source, std::set<std::string> set_keys)
      : source_(std::move(source)), set_(std::move(set_keys)) {}

  const std::string& source() const { return source_; }
  // Where `key` was given: "--set" for a key set on the command line, the source otherwise.
  std::string where(const std::string& key) const { return set_.count(key) ? std::string("--set") : source_; }
  // Throws ConfigError "WHERE: key: message", the form of every config error.
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw ConfigError(where(key) + ": " + key + ": " + message);
  }

 private:
  std::string source_;
  std::set<std::string> set_;  // keys given by --set
};

}  // namespace grainmesh
