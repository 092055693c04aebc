#include "pipelines/key_patterns.hpp"

#include <algorithm>

namespace grainmesh {

namespace {

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

}  // namespace

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

std::string unknown_key_hint(const std::string& key, const std::vector<std::string>& known) {
  if (const std::string nearest = nearest_key(key, known); !nearest.empty()) return " (did you mean " + nearest + "?)";
  // The section's keys when the section exists, so typos are easy to fix.
  const std::string section = key.substr(0, key.find('.') + 1);
  std::string hint;
  for (const auto& k : known)
    if (!section.empty() && k.rfind(section, 0) == 0) hint += (hint.empty() ? "" : ", ") + k;
  return hint.empty() ? "" : " (known here: " + hint + ")";
}

}  // namespace grainmesh
