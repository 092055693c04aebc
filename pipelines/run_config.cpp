#include "pipelines/run_config.hpp"

#include <cstdint>
#include <cstdio>
#include <map>

#include "pipelines/config_keys.hpp"
#include "pipelines/config_values.hpp"
#include "pipelines/default_config.hpp"
#include "pipelines/export_command.hpp"

namespace grainmesh {

const std::vector<std::string>& run_own_config_keys() {
  static const std::vector<std::string> keys = keys_of(kRunKey);
  return keys;
}

std::vector<std::string> run_config_keys() {
  std::vector<std::string> keys = tessellate_config_keys();
  for (const auto& k : run_own_config_keys()) keys.push_back(k);
  for (const auto& k : mesh_config_keys()) keys.push_back(k);
  for (const auto& k : export_config_keys()) keys.push_back(k);
  return keys;
}

const char* default_run_config() { return kDefaultRunConfig; }

std::string config_ini(const Config& config, const std::vector<std::string>& notes) {
  // "a.b.c" is key c of section [a.b]; sections in order of first appearance.
  std::vector<std::string> order;
  std::map<std::string, std::string> body;
  for (const auto& [key, value] : config.entries()) {
    const auto dot = key.rfind('.');
    const std::string section = dot == std::string::npos ? "" : key.substr(0, dot);
    if (!body.count(section)) order.push_back(section);
    body[section] += key.substr(dot + 1) + " = " + value + "\n";
  }
  std::string text = "# The resolved config of a grainmesh run: `grainmesh run config.ini -o OUT` repeats it.\n";
  for (const std::string& note : notes) text += "# " + note + "\n";
  for (const std::string& s : order) text += "\n[" + s + "]\n" + body[s];
  return text;
}

std::string config_fingerprint(const Config& c) {
  std::string text;
  for (const auto& [key, value] : c.entries())
    if (key != "mesh.threads" && key != kTimeLimitKey) text += key + "=" + value + "\n";
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a, 64 bits
  for (const unsigned char ch : text) h = (h ^ ch) * 0x100000001b3ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

}  // namespace grainmesh
