// The command line every grainmesh command shares: its options parsed (Boost), -o OUT and
// --set, the config a command reads and the part of it a stage takes, and errors that
// name the config they came from. main.cpp's commands are built from these.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "common/deadline.hpp"
#include "common/errors.hpp"
#include "pipelines/config.hpp"

namespace grainmesh {

namespace po = boost::program_options;

// A stage command's run on its config and output directory.
using Runner = void (*)(const Config&, const std::filesystem::path&);

// The config keys a command reads (config_keys.hpp); 0 for none.
unsigned command_keys(const std::string& name);

// Parses a command's arguments against `desc` (which gets --help) with the positional
// arguments `positional`, in order. Empty when --help was asked for (and answered).
std::optional<po::variables_map> parse_options(const std::string& name, po::options_description desc,
                                               const std::vector<std::string>& positional,
                                               const std::vector<std::string>& args);

// What an interrupt leaves of OUT (-o): nothing, and the line it prints says so.
void announce_output(const po::variables_map& vm);

// -o OUT and --set KEY=VALUE, which every command that writes takes.
void add_output_options(po::options_description& desc, const char* output_help);

// Parses `grainmesh NAME INPUT -o OUT [--set KEY=VALUE ...]` and any options of the
// command's own in `desc`. Empty when --help was asked for (and answered).
std::optional<po::variables_map> parse_command(const std::string& name, po::options_description desc,
                                               const std::string& input, const std::string& input_help,
                                               const std::vector<std::string>& args);

// The --set KEY=VALUE overrides given, in order.
std::vector<std::string> overrides(const po::variables_map& vm);

// A stage command's part of a config: one config serves every command, so a key that any
// stage of `run` knows is accepted (and left to its stage), any other refused.
Config stage_part(const Config& c, const std::vector<std::string>& stage_keys);

// The config of a command whose config file is optional (--config): the file with the
// --set overrides, or the overrides alone; the part of it that `stage_keys` name.
Config optional_config(const po::variables_map& vm, const std::vector<std::string>& stage_keys);

// A command of the form `grainmesh NAME CONFIG -o OUT [--set KEY=VALUE ...]`.
int config_command(const std::string& name, const std::vector<std::string>& args, Runner run);

// A run config: the CONFIG argument's file, or the embedded default, with --set.
Config run_config(const po::variables_map& vm);

// The same error, its message starting with the config file's name.
template <typename E>
E naming_source(const E& e, const Config& c) {
  const std::string msg = e.what();
  return E(msg.rfind(c.source(), 0) == 0 || msg.rfind("--set", 0) == 0 ? msg : c.source() + ": " + msg);
}

// Runs `run`, its config and geometry errors starting with the config's name.
template <typename F>
void naming_errors(const Config& config, F&& run) {
  try {
    run();
  } catch (const ConfigError& e) {
    throw naming_source(e, config);
  } catch (const GeometryError& e) {
    throw naming_source(e, config);
  } catch (const TimeLimitError& e) {
    throw naming_source(e, config);
  }
}

}  // namespace grainmesh
