#include "pipelines/config.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/parsers.hpp>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "pipelines/key_patterns.hpp"

namespace grainmesh {

namespace po = boost::program_options;

namespace {

// Where Boost's INI reader stops: the first line that, without its comment, is neither
// blank, a [section] nor KEY = VALUE.
std::string describe_bad_line(std::string_view text) {
  int number = 0;
  while (!text.empty()) {
    ++number;
    const auto end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    line = line.substr(0, line.find('#'));
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.front()))) line.remove_prefix(1);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.remove_suffix(1);
    if (line.empty() || (line.front() == '[' && line.back() == ']') || line.find('=') != std::string_view::npos)
      continue;
    std::string shown(line.substr(0, 60));
    for (char& ch : shown)
      if (!std::isprint(static_cast<unsigned char>(ch))) ch = '?';
    return "line " + std::to_string(number) + ": '" + shown + (line.size() > 60 ? "...'" : "'") +
           " is not KEY = VALUE, a [section] or a # comment";
  }
  return "a line is not KEY = VALUE, a [section] or a # comment";
}

}  // namespace

Config Config::from_file(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::ifstream in(file);
  if (!in) throw IoError(file.string() + ": cannot open config file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return from_text(buffer.str(), file.string(), overrides);
}

Config Config::from_text(std::string_view text, std::string source, const std::vector<std::string>& overrides) {
  Config c;
  // Editors on Windows start UTF-8 files with a byte order mark.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::istringstream in{std::string(text)};
  try {
    const po::options_description none;
    for (const auto& opt : po::parse_config_file(in, none, /*allow_unregistered=*/true).options)
      c.entries_.emplace_back(opt.string_key, opt.value.empty() ? std::string() : opt.value.front());
  } catch (const po::invalid_config_file_syntax&) {
    // Not e.what(): Boost substitutes the line into its message until no placeholder is
    // left, forever if the line holds one ("%invalid_line%"; found by fuzzing).
    throw ConfigError(source + ": " + describe_bad_line(text));
  } catch (const po::error& e) {
    throw ConfigError(source + ": " + e.what());
  }

  std::vector<std::pair<std::string, std::string>> set;
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos || eq == 0) throw ConfigError("--set " + o + ": expected KEY=VALUE");
    set.emplace_back(trimmed(o.substr(0, eq)), trimmed(o.substr(eq + 1)));
  }
  std::set<std::string> set_keys;
  for (const auto& kv : set) set_keys.insert(kv.first);
  std::erase_if(c.entries_, [&](const auto& kv) { return set_keys.count(kv.first) > 0; });
  c.origin_ = ConfigOrigin(std::move(source), std::move(set_keys));
  // KEY= (nothing) removes KEY: its default applies, or another key can take its place.
  std::erase_if(set, [](const auto& kv) { return kv.second.empty(); });
  c.entries_.insert(c.entries_.end(), set.begin(), set.end());
  return c;
}

void Config::check_keys(const std::vector<std::string>& known) const {
  for (const auto& entry : entries_) {
    const std::string& key = entry.first;
    if (std::none_of(known.begin(), known.end(), [&](const std::string& k) { return key_matches(k, key); }))
      throw ConfigError(origin_.where(key) + ": unknown key '" + key + "'" + unknown_key_hint(key, known) +
                        "; grainmesh keys lists them all");
  }
}

Config Config::subset(const std::vector<std::string>& known) const {
  Config c;
  c.origin_ = origin_;
  for (const auto& entry : entries_)
    if (std::any_of(known.begin(), known.end(), [&](const std::string& k) { return key_matches(k, entry.first); }))
      c.entries_.push_back(entry);
  return c;
}

std::vector<std::string> Config::names_in(const std::string& section) const {
  const std::string prefix = section + ".";
  std::vector<std::string> names;
  for (const auto& [key, value] : entries_) {
    const auto dot = key.rfind('.');
    if (key.rfind(prefix, 0) != 0 || dot <= prefix.size()) continue;
    std::string name = key.substr(prefix.size(), dot - prefix.size());
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(std::move(name));
  }
  return names;
}

bool Config::has(const std::string& key) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const auto& kv) { return kv.first == key; });
}

std::vector<std::string> Config::all(const std::string& key) const {
  std::vector<std::string> v;
  for (const auto& [k, value] : entries_)
    if (k == key) v.push_back(value);
  return v;
}

std::optional<std::string> Config::optional_text(const std::string& key) const {
  const auto v = all(key);
  if (v.empty()) return std::nullopt;
  if (v.size() > 1) fail(key, "given " + std::to_string(v.size()) + " times, expected once");
  return v.front();
}

std::string Config::text(const std::string& key) const {
  auto v = optional_text(key);
  if (!v) fail(key, "missing (required)");
  return *v;
}

namespace {
template <typename T>
std::optional<T> parse_whole(const std::string& s) {
  T v{};
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (first < last && *first == '+') ++first;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (ec != std::errc() || ptr != last) return std::nullopt;
  return v;
}
}  // namespace

double Config::number(const std::string& key) const {
  const std::string s = text(key);
  const auto v = parse_whole<double>(s);
  if (!v || !std::isfinite(*v)) fail(key, "'" + s + "' is not a number");
  return *v;
}

double Config::number(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

long long Config::integer(const std::string& key, long long fallback) const {
  if (!has(key)) return fallback;
  const std::string s = text(key);
  const auto v = parse_whole<long long>(s);
  if (!v) fail(key, "'" + s + "' is not an integer");
  return *v;
}

std::uint64_t Config::unsigned_integer(const std::string& key, std::uint64_t fallback) const {
  if (!has(key)) return fallback;
  const std::string s = text(key);
  const auto v = parse_whole<std::uint64_t>(s);
  if (!v) fail(key, "'" + s + "' is not a non-negative integer");
  return *v;
}

bool Config::flag(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  std::string s = text(key);
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return std::tolower(ch); });
  if (s == "true" || s == "yes" || s == "on" || s == "1") return true;
  if (s == "false" || s == "no" || s == "off" || s == "0") return false;
  fail(key, "'" + s + "' is not true or false");
}

}  // namespace grainmesh
