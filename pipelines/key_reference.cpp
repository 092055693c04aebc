#include "pipelines/key_reference.hpp"

#include <cstdio>
#include <utility>

#include "pipelines/config_keys.hpp"

namespace grainmesh {

std::string key_reference(unsigned commands) {
  // Sections in the order they first appear, each with all its keys.
  std::vector<std::string> sections;
  std::vector<std::string> bodies;
  for (const ConfigKey& k : config_key_table()) {
    if ((k.commands & commands) == 0) continue;
    const std::string key = k.key;
    const std::string section = key.substr(0, key.find('.'));
    std::size_t s = 0;
    while (s < sections.size() && sections[s] != section) ++s;
    if (s == sections.size()) sections.push_back(section), bodies.emplace_back();
    char line[96];
    std::snprintf(line, sizeof line, "  %-30s = %-18s ", k.key, k.default_text);
    bodies[s] += std::string(line) + k.meaning + "\n";
  }
  std::string text;
  for (std::size_t s = 0; s < sections.size(); ++s) text += (s ? "\n[" : "[") + sections[s] + "]\n" + bodies[s];
  return text;
}

namespace {

// The commands that read a key, as the reference lists them.
std::string command_names(unsigned commands) {
  static const std::pair<unsigned, const char*> kNames[] = {{kTessellateKey, "tessellate"}, {kMeshKey, "mesh"},
                                                            {kExportKey, "export"},         {kRunKey, "run"},
                                                            {kDomainKey, "domain"},         {kSweepKey, "sweep"}};
  std::string names;
  for (const auto& [bit, name] : kNames)
    if (commands & bit) names += (names.empty() ? "" : ", ") + std::string(name);
  return names;
}

// A table cell: '|' escaped.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|' && (out.empty() || out.back() != '\\')) out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string key_reference_markdown() {
  std::string text =
      "# Config keys\n\n"
      "Every key grainmesh reads, generated from the table its config readers check keys against\n"
      "(`pipelines/config_keys.cpp`): `grainmesh keys --markdown` prints this page, and a test fails\n"
      "when it and the code disagree. `run` reads the keys of tessellate, mesh and export and its\n"
      "own; `sweep` a run's and its own. `phase.*.KEY` stands for any phase's name. Lengths are in\n"
      "the config's unit (micrometres with the default `export.convert_to_meters = 1e-6`), moduli\n"
      "in Pa. `grainmesh keys [COMMAND]` prints the same as one line per key.\n";
  std::string section;
  for (const ConfigKey& k : config_key_table()) {
    const std::string key = k.key;
    const std::string s = key.substr(0, key.find('.'));
    if (s != section) {
      section = s;
      text += "\n## [" + s + "]\n\n| key | read by | default | meaning |\n| --- | --- | --- | --- |\n";
    }
    std::string def = "–";  // en dash: none, or required
    if (std::string(k.default_text) != "-") def.assign("`").append(k.default_text).append("`");
    text += "| `" + key + "` | " + command_names(k.commands) + " | " + cell(def) + " | " +
            cell(k.details != nullptr ? k.details : k.meaning) + " |\n";
  }
  return text;
}

}  // namespace grainmesh
