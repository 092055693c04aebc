#include "pipelines/command_mains.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include <boost/program_options.hpp>

#include "common/errors.hpp"
#include "pipelines/command_line.hpp"
#include "pipelines/config.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/converge_command.hpp"
#include "pipelines/domain_command.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/key_reference.hpp"
#include "pipelines/mesh_command.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/run_command.hpp"
#include "pipelines/sweep_command.hpp"
#include "pipelines/tessellate_command.hpp"

namespace grainmesh {

// `grainmesh keys [COMMAND]`: the key reference, of one command or all; `--markdown`:
// all of it as docs/keys.md.
int keys_main(const std::vector<std::string>& args) {
  if (args.size() == 1 && args[0] == "--markdown") {
    std::cout << key_reference_markdown();
    return kExitOk;
  }
  if (args.size() > 1) throw ConfigError("keys: give at most one command (run, tessellate, mesh, export, domain, sweep)");
  const unsigned keys = args.empty() ? ~0u : command_keys(args[0]);
  if (keys == 0)
    throw ConfigError("keys: unknown command '" + args[0] + "' (run, tessellate, mesh, export, domain, sweep)");
  std::cout << key_reference(keys);
  return kExitOk;
}

// `grainmesh mesh TESSELLATION.json -o OUT [--config MESH.ini] [--set KEY=VALUE ...]`.
int mesh_main(const std::vector<std::string>& args) {
  po::options_description desc("grainmesh mesh TESSELLATION.json -o OUT [--config MESH.ini] [--set KEY=VALUE ...]");
  desc.add_options()("config", po::value<std::string>(), "mesh config file (INI) with mesh.* and phase.NAME.size keys");
  const auto vm = parse_command("mesh", desc, "tessellation", "tessellation.json written by grainmesh tessellate", args);
  if (!vm) return kExitOk;
  const Config config = optional_config(*vm, mesh_config_keys());
  run_mesh_command((*vm)["tessellation"].as<std::string>(), config, (*vm)["output"].as<std::string>());
  return kExitOk;
}

// `grainmesh export MESH.vtu -o CASE [--config EXPORT.ini] [--set KEY=VALUE ...]`.
int export_main(const std::vector<std::string>& args) {
  po::options_description desc("grainmesh export MESH.vtu -o CASE [--config EXPORT.ini] [--set KEY=VALUE ...]");
  desc.add_options()("config", po::value<std::string>(), "export config file (INI) with export.*, load.* and phase.NAME.E/nu keys");
  const auto vm = parse_command("export", desc, "mesh", "mesh.vtu written by grainmesh mesh or domain", args);
  if (!vm) return kExitOk;
  const Config config = optional_config(*vm, export_config_keys());
  run_export_command((*vm)["mesh"].as<std::string>(), config, (*vm)["output"].as<std::string>());
  return kExitOk;
}

// `grainmesh run [CONFIG] -o OUT [--set KEY=VALUE ...]`: without CONFIG, the embedded default.
int run_main(const std::vector<std::string>& args) {
  po::options_description desc("grainmesh run [CONFIG] -o OUT [--solve] [--force] [--quiet] [--set KEY=VALUE ...]");
  desc.add_options()("config", po::value<std::string>(), "config file (INI); none = the embedded default (data/default.ini)")(
      "solve", "also solve the case with solidDisplacementFoam and homogenise (report.json: effective)")(
      "force", "replace an OUT that holds a solved run even without --solve")(
      "quiet,q", "no stage and progress display on the terminal");
  add_output_options(desc, "output directory (replaced only when it holds an earlier output of this command)");
  const auto parsed = parse_options("run", desc, {"config"}, args);
  if (!parsed) return kExitOk;
  const po::variables_map& vm = *parsed;
  if (!vm.count("output")) throw ConfigError("run: missing -o OUT (the output directory)");
  announce_output(vm);
  const Config config = run_config(vm);
  refuse_unsolved_over_solved(vm["output"].as<std::string>(), vm.count("solve") > 0, vm.count("force") > 0);
  naming_errors(config, [&] {
    run_run_command(config, vm["output"].as<std::string>(), vm.count("solve") > 0, vm.count("quiet") > 0);
  });
  return kExitOk;
}

// `grainmesh converge [CONFIG] -o DIR [--levels K] [--start N] [--set KEY=VALUE ...]`.
int converge_main(const std::vector<std::string>& args) {
  po::options_description desc("grainmesh converge [CONFIG] -o DIR [--levels K] [--start N] [--set KEY=VALUE ...]");
  desc.add_options()("config", po::value<std::string>(), "run config (INI); none = the embedded default")(
      "levels", po::value<int>()->default_value(ConvergeOptions{}.levels),
      "nested levels, 3 to 5 (each splits every element of the one before)")(
      "start", po::value<int>()->default_value(ConvergeOptions{}.start),
      "triangles (tetrahedra) per grain of the coarsest level");
  add_output_options(desc, "the study's directory (replaced only when it holds an earlier study)");
  const auto parsed = parse_options("converge", desc, {"config"}, args);
  if (!parsed) return kExitOk;
  const po::variables_map& vm = *parsed;
  if (!vm.count("output")) throw ConfigError("converge: missing -o DIR (the study's directory)");
  announce_output(vm);
  const Config config = run_config(vm);
  const ConvergeOptions o{.levels = vm["levels"].as<int>(), .start = vm["start"].as<int>()};
  naming_errors(config, [&] { run_converge_command(config, vm["output"].as<std::string>(), o); });
  return kExitOk;
}

// `grainmesh sweep SWEEP.ini -o DIR [--jobs N] [--shard I/N] [--solve] [--set ...]`, or
// `grainmesh sweep --collect DIR`.
int sweep_main(const std::vector<std::string>& args) {
  po::options_description desc("grainmesh sweep SWEEP.ini -o DIR [--jobs N] [--shard I/N] [--solve] | --collect DIR");
  desc.add_options()("config", po::value<std::string>(), "sweep config (INI) with [sweep]")(
      "jobs", po::value<int>()->default_value(1), "runs at a time")(
      "shard", po::value<std::string>(), "I/N: run only the I-th of N deterministic parts")(
      "solve", "solve and homogenise every run")("collect", po::value<std::string>(),
                                                  "merge the reports of DIR into DIR/summary.csv");
  add_output_options(desc, "the sweep's directory (runs resume there)");
  const auto parsed = parse_options("sweep", desc, {"config"}, args);
  if (!parsed) return kExitOk;
  const po::variables_map& vm = *parsed;
  if (vm.count("collect")) {
    collect_sweep(vm["collect"].as<std::string>());
    return kExitOk;
  }
  if (!vm.count("config")) throw ConfigError("sweep: missing the SWEEP.ini file argument");
  if (!vm.count("output")) throw ConfigError("sweep: missing -o DIR (the sweep's directory)");
  SweepOptions o;
  o.jobs = vm["jobs"].as<int>();
  if (o.jobs < 1 || o.jobs > 1024) throw ConfigError("sweep: --jobs must be between 1 and 1024");
  if (vm.count("shard")) {
    const std::string s = vm["shard"].as<std::string>();
    if (std::sscanf(s.c_str(), "%d/%d", &o.shard, &o.shards) != 2 || o.shards < 1 || o.shard < 1 || o.shard > o.shards)
      throw ConfigError("sweep: --shard " + s + ": expected I/N with 1 <= I <= N");
  }
  o.solve = vm.count("solve") > 0;
  const Config config = Config::from_file(vm["config"].as<std::string>(), overrides(vm));
  run_sweep_command(config, vm["output"].as<std::string>(), o);
  return kExitOk;
}

// `grainmesh check TESSELLATION.json MESH.vtu`.
int check_main(const std::vector<std::string>& args) {
  po::options_description desc("grainmesh check TESSELLATION.json MESH.vtu");
  desc.add_options()("tessellation", po::value<std::string>(), "tessellation.json")(
      "mesh", po::value<std::string>(), "mesh.vtu written by grainmesh mesh");
  const auto parsed = parse_options("check", desc, {"tessellation", "mesh"}, args);
  if (!parsed) return kExitOk;
  const po::variables_map& vm = *parsed;
  if (!vm.count("tessellation") || !vm.count("mesh"))
    throw ConfigError("check: give the tessellation.json and the mesh.vtu to check");
  run_check_command(vm["tessellation"].as<std::string>(), vm["mesh"].as<std::string>());
  return kExitOk;
}

// `grainmesh tessellate CONFIG -o OUT [--set KEY=VALUE ...]`.
int tessellate_main(const std::vector<std::string>& args) {
  return config_command("tessellate", args, [](const Config& c, const std::filesystem::path& out) {
    run_tessellate_command(stage_part(c, tessellate_config_keys()), out);
  });
}

// `grainmesh domain CONFIG -o OUT [--set KEY=VALUE ...]`.
int domain_main(const std::vector<std::string>& args) { return config_command("domain", args, run_domain_command); }

}  // namespace grainmesh
