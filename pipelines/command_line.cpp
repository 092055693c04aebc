#include "pipelines/command_line.hpp"

#include <algorithm>
#include <iostream>

#include "common/interrupt.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/key_reference.hpp"
#include "pipelines/run_config.hpp"

namespace grainmesh {

// The config keys a command reads (config_keys.hpp); 0 for none.
unsigned command_keys(const std::string& name) {
  if (name == "tessellate") return kTessellateKey;
  if (name == "mesh") return kMeshKey;
  if (name == "export") return kExportKey;
  if (name == "domain") return kDomainKey;
  if (name == "run" || name == "converge") return kTessellateKey | kMeshKey | kExportKey | kRunKey;
  if (name == "sweep") return kTessellateKey | kMeshKey | kExportKey | kRunKey | kSweepKey;
  return 0;
}

// Parses a command's arguments against `desc` (which gets --help) with the positional
// arguments `positional`, in order. Empty when --help was asked for (and answered).
std::optional<po::variables_map> parse_options(const std::string& name, po::options_description desc,
                                               const std::vector<std::string>& positional,
                                               const std::vector<std::string>& args) {
  desc.add_options()("help,h", "show this help");
  po::positional_options_description pos;
  for (const std::string& p : positional) pos.add(p.c_str(), 1);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(args).options(desc).positional(pos).run(), vm);
  } catch (const po::error_with_option_name& e) {
    // Boost's what() substitutes the option as typed into its message until no placeholder
    // is left, forever for an option such as --%option% (found by fuzzing the config reader,
    // which had the same trouble); with a '%' about, the message is built here.
    if (std::any_of(args.begin(), args.end(), [](const std::string& a) { return a.find('%') != std::string::npos; }))
      throw ConfigError(name + ": cannot read option '" + e.get_option_name() + "' (see grainmesh " + name + " --help)");
    throw ConfigError(name + ": " + e.what());
  } catch (const po::error& e) {
    throw ConfigError(name + ": " + e.what());
  }
  if (vm.count("help")) {
    std::cout << desc << "\nConfig keys (grainmesh keys " << name << "):\n" << key_reference(command_keys(name))
              << "\nSee docs/" << (name == "check" ? std::string("mesh") : name) << ".md.\n";
    return std::nullopt;
  }
  return vm;
}

// What an interrupt leaves of OUT (-o): nothing, and the line it prints says so.
void announce_output(const po::variables_map& vm) {
  if (vm.count("output"))
    set_interrupt_message("nothing written to " + std::filesystem::absolute(vm["output"].as<std::string>()).lexically_normal().string());
}

// -o OUT and --set KEY=VALUE, which every command that writes takes.
void add_output_options(po::options_description& desc, const char* output_help) {
  desc.add_options()("output,o", po::value<std::string>(), output_help)(
      "set", po::value<std::vector<std::string>>()->composing(), "set a config key, e.g. --set section.key=value");
}

// Parses `grainmesh NAME INPUT -o OUT [--set KEY=VALUE ...]` and any options of the
// command's own in `desc`. Empty when --help was asked for (and answered).
std::optional<po::variables_map> parse_command(const std::string& name, po::options_description desc,
                                               const std::string& input, const std::string& input_help,
                                               const std::vector<std::string>& args) {
  desc.add_options()(input.c_str(), po::value<std::string>(), input_help.c_str());
  add_output_options(desc, "output directory (replaced only when it holds an earlier output of this command)");
  const auto parsed = parse_options(name, desc, {input}, args);
  if (!parsed) return std::nullopt;
  const po::variables_map& vm = *parsed;
  if (!vm.count(input)) throw ConfigError(name + ": missing the " + input + " file argument");
  if (!vm.count("output")) throw ConfigError(name + ": missing -o OUT (the output directory)");
  announce_output(vm);
  return vm;
}

std::vector<std::string> overrides(const po::variables_map& vm) {
  return vm.count("set") ? vm["set"].as<std::vector<std::string>>() : std::vector<std::string>{};
}

// A stage command's part of a config: one config serves every command, so a key that any
// stage of `run` knows is accepted (and left to its stage), any other refused.
Config stage_part(const Config& c, const std::vector<std::string>& stage_keys) {
  c.check_keys(run_config_keys());
  return c.subset(stage_keys);
}

// The config of a command whose config file is optional (--config): the file with the
// --set overrides, or the overrides alone; the part of it that `stage_keys` name.
Config optional_config(const po::variables_map& vm, const std::vector<std::string>& stage_keys) {
  return stage_part(vm.count("config") ? Config::from_file(vm["config"].as<std::string>(), overrides(vm))
                                       : Config::from_text("", "--set", overrides(vm)),
                    stage_keys);
}

// A command of the form `grainmesh NAME CONFIG -o OUT [--set KEY=VALUE ...]`.
int config_command(const std::string& name, const std::vector<std::string>& args, Runner run) {
  const auto vm = parse_command(name, po::options_description("grainmesh " + name + " CONFIG -o OUT [--set KEY=VALUE ...]"),
                                "config", "config file (INI)", args);
  if (!vm) return kExitOk;
  const Config config = Config::from_file((*vm)["config"].as<std::string>(), overrides(*vm));
  naming_errors(config, [&] { run(config, (*vm)["output"].as<std::string>()); });
  return kExitOk;
}

// A run config: the CONFIG argument's file, or the embedded default, with --set.
Config run_config(const po::variables_map& vm) {
  return vm.count("config") ? Config::from_file(vm["config"].as<std::string>(), overrides(vm))
                            : Config::from_text(default_run_config(), "default config", overrides(vm));
}

}  // namespace grainmesh
