#include "pipelines/config.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/parsers.hpp>

#include "common/errors.hpp"
#include "common/format.hpp"

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

namespace {

// A known key matches a key when their dot-separated parts agree, "*" matching any one.
bool key_matches(std::string_view pattern, std::string_view key) {
  while (true) {
    const auto pd = pattern.find('.'), kd = key.find('.');
    const std::string_view ph = pattern.substr(0, pd), kh = key.substr(0, kd);
    if (ph != "*" ? ph != kh : kh.empty()) return false;
    if (pd == std::string_view::npos || kd == std::string_view::npos) return pd == kd;
    pattern.remove_prefix(pd + 1);
    key.remove_prefix(kd + 1);
  }
}

// Levenshtein's edit distance.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// The known key nearest `key` when it is a slip away (a letter or two: US spelling,
// a typo), a "*" part taken as the key's own; empty otherwise.
std::string nearest_key(const std::string& key, const std::vector<std::string>& known) {
  std::string best;
  std::size_t best_distance = 3;  // at most two edits
  for (const std::string& k : known) {
    // The pattern with its "*" parts filled from the key's.
    std::string filled;
    std::size_t kp = 0, pp = 0;
    while (pp <= k.size()) {
      const std::size_t pe = std::min(k.find('.', pp), k.size()), ke = std::min(key.find('.', kp), key.size());
      const std::string part = k.substr(pp, pe - pp);
      filled += (filled.empty() ? "" : ".") + (part == "*" && kp <= key.size() ? key.substr(kp, ke - kp) : part);
      pp = pe + 1;
      kp = ke + 1;
    }
    const std::size_t d = edit_distance(key, filled);
    if (d < best_distance && 4 * d <= key.size()) best_distance = d, best = filled;  // a slip, not another short key
  }
  return best;
}

}  // namespace

void Config::check_keys(const std::vector<std::string>& known) const {
  for (const auto& entry : entries_) {
    const std::string& key = entry.first;
    if (std::none_of(known.begin(), known.end(), [&](const std::string& k) { return key_matches(k, key); })) {
      // Point at the section's keys when the section exists, so typos are easy to fix.
      const std::string section = key.substr(0, key.find('.') + 1);
      std::string hint;
      for (const auto& k : known)
        if (!section.empty() && k.rfind(section, 0) == 0) hint += (hint.empty() ? "" : ", ") + k;
      const std::string nearest = nearest_key(key, known);
      throw ConfigError(origin_.where(key) + ": unknown key '" + key + "'" +
                        (!nearest.empty() ? " (did you mean " + nearest + "?)"
                         : hint.empty()   ? ""
                                          : " (known here: " + hint + ")") +
                        "; grainmesh keys lists them all");
    }
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

double read_time_limit(const Config& c) {
  if (c.optional_text(kTimeLimitKey) == "none") return std::numeric_limits<double>::infinity();
  const double seconds = c.number(kTimeLimitKey, kDefaultTimeLimitSeconds);
  if (!(seconds > 0.0) || !std::isfinite(seconds))
    c.fail(kTimeLimitKey, "must be a positive number of seconds or none, got " + c.text(kTimeLimitKey));
  return seconds;
}

double positive(const Config& c, const std::string& key) {
  if (!c.has(key)) c.fail(key, "missing (required)");
  const double v = c.number(key);
  if (!(v > 0.0) || !std::isfinite(v)) c.fail(key, "must be positive, got " + c.text(key));
  return v;
}

double positive(const Config& c, const std::string& key, double fallback) {
  const double v = c.number(key, fallback);
  if (!(v > 0.0)) c.fail(key, "must be positive, got " + c.text(key));
  return v;
}

std::string one_of_keys(const Config& c, const std::string& a, const std::string& b) {
  if (c.has(a) && c.has(b)) c.fail(b, "give either " + a + " or " + b + ", not both");
  return c.has(b) ? b : a;
}

}  // namespace grainmesh
