// Configuration files: INI, read with Boost.Program_options, plus KEY=VALUE overrides
// from the command line (--set). Keys are "section.name"; '#' starts a comment. Values
// are checked where they are read, and every error names the file and the key.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pipelines/config_origin.hpp"

namespace grainmesh {

class Config {
 public:
  // Reads `file`; each override "KEY=VALUE" replaces every value the file gives KEY (give
  // the same KEY several times to set several values), "KEY=" removes KEY. Errors about a
  // key set so name "--set", not the file. Throws ConfigError or IoError.
  static Config from_file(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
  // The same from text; `source` names it in messages.
  static Config from_text(std::string_view text, std::string source, const std::vector<std::string>& overrides = {});

  // Throws ConfigError naming the first key that is not in `known`; a part "*" of a
  // known key stands for any one name ("phase.*.fraction").
  void check_keys(const std::vector<std::string>& known) const;

  bool has(const std::string& key) const;
  // Every value of a key that may repeat, in file order.
  std::vector<std::string> all(const std::string& key) const;
  // The value of a key that must appear once.
  std::string text(const std::string& key) const;
  std::optional<std::string> optional_text(const std::string& key) const;
  double number(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  long long integer(const std::string& key, long long fallback) const;
  std::uint64_t unsigned_integer(const std::string& key, std::uint64_t fallback) const;
  bool flag(const std::string& key, bool fallback) const;

  // The NAMEs of keys "section.NAME.key" (a [section.NAME] in the file), in the order
  // they first appear.
  std::vector<std::string> names_in(const std::string& section) const;

  const std::string& source() const { return origin_.source(); }
  // Where the values came from, for errors found once the config is read.
  const ConfigOrigin& origin() const { return origin_; }
  // "source: key: message", the form of every config error ("--set: key: message" for a
  // key given with --set).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const { origin_.fail(key, message); }

  // The entries whose keys match `known` (patterns as in check_keys): the part of a
  // run's config one stage reads.
  Config subset(const std::vector<std::string>& known) const;

  // The resolved entries (after overrides), in order; for writing config.ini of a run.
  const std::vector<std::pair<std::string, std::string>>& entries() const { return entries_; }

 private:
  ConfigOrigin origin_;
  std::vector<std::pair<std::string, std::string>> entries_;
};

// The dimension of the cell a config describes, decided here and nowhere else: 3 when it
// sets domain.depth (a W x H x D box), 2 otherwise.
inline int cell_dimensions(const Config& config) { return config.has("domain.depth") ? 3 : 2; }

}  // namespace grainmesh
