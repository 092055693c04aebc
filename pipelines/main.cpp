// grainmesh: synthetic microstructures to solver-ready meshes.
// main() is the only place that catches errors: it prints one line and maps the error
// family to the exit code documented in docs/errors.md.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "common/allocator.hpp"
#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "pipelines/command_line.hpp"
#include "pipelines/config.hpp"
#include "pipelines/config_keys.hpp"
#include "pipelines/converge_command.hpp"
#include "pipelines/domain_command.hpp"
#include "pipelines/export_command.hpp"
#include "pipelines/mesh_command.hpp"
#include "pipelines/output_dir.hpp"
#include "pipelines/run_command.hpp"
#include "pipelines/sweep_command.hpp"
#include "pipelines/tessellate_command.hpp"

using namespace grainmesh;

namespace {

constexpr const char* kUsage =
    "usage: grainmesh <command> [options]\n"
    "\n"
    "commands:\n"
    "  run [CONFIG] -o OUT [--solve] [--set KEY=VALUE ...]\n"
    "      tessellate, mesh and export in one go (without CONFIG: the thesis' cell, data/default.ini)\n"
    "  converge [CONFIG] -o DIR [--levels K] [--start N] [--set KEY=VALUE ...]\n"
    "      mesh convergence of the effective properties: K densities from N triangles per grain, doubling\n"
    "  sweep SWEEP.ini -o DIR [--jobs N] [--shard I/N] [--solve] [--set KEY=VALUE ...]\n"
    "  sweep --collect DIR\n"
    "      runs over the cartesian product of the [sweep] lists; resumes; DIR/summary.csv\n"
    "  tessellate CONFIG -o OUT [--set KEY=VALUE ...]\n"
    "      periodic Voronoi/Laguerre grains with phases (see data/examples/grains_*.ini)\n"
    "  mesh TESSELLATION.json -o OUT [--config MESH.ini] [--set KEY=VALUE ...]\n"
    "      mesh every grain of a tessellation, conforming and periodic\n"
    "  export MESH.vtu -o CASE [--config EXPORT.ini] [--set KEY=VALUE ...]\n"
    "      an OpenFOAM case for solidDisplacementFoam from a mesh of grainmesh mesh or domain\n"
    "  check TESSELLATION.json MESH.vtu\n"
    "      check that a mesh conforms to its tessellation (exit 0) or name the violation (exit 3)\n"
    "  domain CONFIG -o OUT [--set KEY=VALUE ...]\n"
    "      mesh a domain given by distance and size functions (see data/examples/)\n"
    "  keys [COMMAND | --markdown]\n"
    "      every config key (of run, tessellate, mesh, export, domain or sweep) with its default and meaning\n"
    "\n"
    "grainmesh <command> --help shows the options of a command and its config keys.\n";

constexpr int kOk = kExitOk;

// `grainmesh keys [COMMAND]`: the key reference, of one command or all; `--markdown`:
// all of it as docs/keys.md.
int keys_main(const std::vector<std::string>& args) {
  if (args.size() == 1 && args[0] == "--markdown") {
    std::cout << key_reference_markdown();
    return kOk;
  }
  if (args.size() > 1) throw ConfigError("keys: give at most one command (run, tessellate, mesh, export, domain, sweep)");
  const unsigned keys = args.empty() ? ~0u : command_keys(args[0]);
  if (keys == 0)
    throw ConfigError("keys: unknown command '" + args[0] + "' (run, tessellate, mesh, export, domain, sweep)");
  std::cout << key_reference(keys);
  return kOk;
}

// `grainmesh mesh TESSELLATION.json -o OUT [--config MESH.ini] [--set KEY=VALUE ...]`.
int mesh_main(const std::vector<std::string>& args) {
  po::options_description desc("grainmesh mesh TESSELLATION.json -o OUT [--config MESH.ini] [--set KEY=VALUE ...]");
  desc.add_options()("config", po::value<std::string>(), "mesh config file (INI) with mesh.* and phase.NAME.size keys");
  const auto vm = parse_command("mesh", desc, "tessellation", "tessellation.json written by grainmesh tessellate", args);
  if (!vm) return kOk;
  const Config config = optional_config(*vm, mesh_config_keys());
  run_mesh_command((*vm)["tessellation"].as<std::string>(), config, (*vm)["output"].as<std::string>());
  return kOk;
}

// `grainmesh export MESH.vtu -o CASE [--config EXPORT.ini] [--set KEY=VALUE ...]`.
int export_main(const std::vector<std::string>& args) {
  po::options_description desc("grainmesh export MESH.vtu -o CASE [--config EXPORT.ini] [--set KEY=VALUE ...]");
  desc.add_options()("config", po::value<std::string>(), "export config file (INI) with export.*, load.* and phase.NAME.E/nu keys");
  const auto vm = parse_command("export", desc, "mesh", "mesh.vtu written by grainmesh mesh or domain", args);
  if (!vm) return kOk;
  const Config config = optional_config(*vm, export_config_keys());
  run_export_command((*vm)["mesh"].as<std::string>(), config, (*vm)["output"].as<std::string>());
  return kOk;
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
  if (!parsed) return kOk;
  const po::variables_map& vm = *parsed;
  if (!vm.count("output")) throw ConfigError("run: missing -o OUT (the output directory)");
  announce_output(vm);
  const Config config = run_config(vm);
  refuse_unsolved_over_solved(vm["output"].as<std::string>(), vm.count("solve") > 0, vm.count("force") > 0);
  naming_errors(config, [&] {
    run_run_command(config, vm["output"].as<std::string>(), vm.count("solve") > 0, vm.count("quiet") > 0);
  });
  return kOk;
}

// `grainmesh converge [CONFIG] -o DIR [--levels K] [--start N] [--set KEY=VALUE ...]`.
int converge_main(const std::vector<std::string>& args) {
  po::options_description desc("grainmesh converge [CONFIG] -o DIR [--levels K] [--start N] [--set KEY=VALUE ...]");
  desc.add_options()("config", po::value<std::string>(), "run config (INI); none = the embedded default")(
      "levels", po::value<int>()->default_value(ConvergeOptions{}.levels), "mesh densities (3 or more)")(
      "start", po::value<int>()->default_value(ConvergeOptions{}.start), "triangles per grain of the coarsest");
  add_output_options(desc, "the study's directory (replaced only when it holds an earlier study)");
  const auto parsed = parse_options("converge", desc, {"config"}, args);
  if (!parsed) return kOk;
  const po::variables_map& vm = *parsed;
  if (!vm.count("output")) throw ConfigError("converge: missing -o DIR (the study's directory)");
  announce_output(vm);
  const Config config = run_config(vm);
  const ConvergeOptions o{.levels = vm["levels"].as<int>(), .start = vm["start"].as<int>()};
  naming_errors(config, [&] { run_converge_command(config, vm["output"].as<std::string>(), o); });
  return kOk;
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
  if (!parsed) return kOk;
  const po::variables_map& vm = *parsed;
  if (vm.count("collect")) {
    collect_sweep(vm["collect"].as<std::string>());
    return kOk;
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
  return kOk;
}

// `grainmesh check TESSELLATION.json MESH.vtu`.
int check_main(const std::vector<std::string>& args) {
  po::options_description desc("grainmesh check TESSELLATION.json MESH.vtu");
  desc.add_options()("tessellation", po::value<std::string>(), "tessellation.json")(
      "mesh", po::value<std::string>(), "mesh.vtu written by grainmesh mesh");
  const auto parsed = parse_options("check", desc, {"tessellation", "mesh"}, args);
  if (!parsed) return kOk;
  const po::variables_map& vm = *parsed;
  if (!vm.count("tessellation") || !vm.count("mesh"))
    throw ConfigError("check: give the tessellation.json and the mesh.vtu to check");
  run_check_command(vm["tessellation"].as<std::string>(), vm["mesh"].as<std::string>());
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  grainmesh::keep_freed_memory();  // the mesher's page faults halved (common/allocator.hpp)
  grainmesh::install_interrupt_handling();  // before any thread starts: Ctrl-C leaves nothing behind
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      std::cout << kUsage;
      return args.empty() ? kExitConfig : kOk;
    }
    if (args[0] == "--version") {
      std::cout << "grainmesh 0.1.0\n";
      return kOk;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "run") return run_main(rest);
    if (args[0] == "sweep") return sweep_main(rest);
    if (args[0] == "converge") return converge_main(rest);
    if (args[0] == "tessellate")
      return config_command("tessellate", rest, [](const Config& c, const std::filesystem::path& out) {
        run_tessellate_command(stage_part(c, tessellate_config_keys()), out);
      });
    if (args[0] == "mesh") return mesh_main(rest);
    if (args[0] == "check") return check_main(rest);
    if (args[0] == "export") return export_main(rest);
    if (args[0] == "domain") return config_command("domain", rest, run_domain_command);
    if (args[0] == "keys") return keys_main(rest);
    throw ConfigError("unknown command '" + args[0] + "' (run grainmesh --help)");
  } catch (const Error& e) {
    wait_if_interrupted();  // an error the interrupt caused (a child it stopped) is not the run's
    std::fprintf(stderr, "%s%s\n", kErrorPrefix.data(), e.what());
    return exit_code_of(e);
  } catch (const std::exception& e) {
    wait_if_interrupted();
    std::fprintf(stderr, "grainmesh: internal error: %s\n", e.what());
    return kExitInternal;
  }
}
