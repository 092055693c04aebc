// grainmesh: synthetic microstructures to solver-ready meshes.
// main() is the only place that catches errors: it prints one line and maps the error
// family to the exit code documented in docs/errors.md.
#include <signal.h>

#include <cstdio>
#include <new>
#include <iostream>
#include <string>
#include <vector>

#include "common/allocator.hpp"
#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "pipelines/command_mains.hpp"

using namespace grainmesh;

namespace {

// SIGINT, SIGTERM and SIGHUP blocked before any shared library's constructor runs: OpenBLAS (under
// CHOLMOD) starts its threads in one, and a thread that does not block them could take the
// signal with its default action and kill the process uncleaned. install_interrupt_handling
// blocks them too and waits for them on its own thread.
void block_interrupts_early(int, char**, char**) {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
}
__attribute__((section(".preinit_array"), used)) void (*const kBlockInterruptsEarly)(int, char**, char**) =
    block_interrupts_early;

constexpr const char* kUsage =
    "usage: grainmesh <command> [options]\n"
    "\n"
    "commands:\n"
    "  run [CONFIG] -o OUT [--solve] [--set KEY=VALUE ...]\n"
    "      tessellate, mesh and export in one go (without CONFIG: the thesis' cell, data/default.ini)\n"
    "  converge [CONFIG] -o DIR [--levels K] [--start N] [--set KEY=VALUE ...]\n"
    "      mesh convergence of the effective properties: meshed at N elements per grain, K nested levels\n"
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

}  // namespace

int main(int argc, char** argv) {
  grainmesh::ask_for_huge_pages(argv);  // may exec the program again, so before anything else
  grainmesh::keep_freed_memory();  // the mesher's page faults halved (common/allocator.hpp)
  grainmesh::install_interrupt_handling();  // before any thread starts: Ctrl-C leaves nothing behind
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      std::cout << kUsage;
      return args.empty() ? kExitConfig : kExitOk;
    }
    if (args[0] == "--version") {
      std::cout << "grainmesh 0.1.0\n";
      return kExitOk;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "run") return run_main(rest);
    if (args[0] == "sweep") return sweep_main(rest);
    if (args[0] == "converge") return converge_main(rest);
    if (args[0] == "tessellate") return tessellate_main(rest);
    if (args[0] == "mesh") return mesh_main(rest);
    if (args[0] == "check") return check_main(rest);
    if (args[0] == "export") return export_main(rest);
    if (args[0] == "domain") return domain_main(rest);
    if (args[0] == "keys") return keys_main(rest);
    throw ConfigError("unknown command '" + args[0] + "' (run grainmesh --help)");
  } catch (const Error& e) {
    wait_if_interrupted();  // an error the interrupt caused (a child it stopped) is not the run's
    std::fprintf(stderr, "%s%s\n", kErrorPrefix.data(), e.what());
    return exit_code_of(e);
  } catch (const std::bad_alloc&) {
    wait_if_interrupted();
    std::fprintf(stderr, "%sout of memory: the run needs more than this process may take (the machine's, its control "
                 "group's or ulimit -v's limit); mesh coarser, or fewer grains\n", kErrorPrefix.data());
    return kExitInternal;
  } catch (const std::exception& e) {
    wait_if_interrupted();
    std::fprintf(stderr, "grainmesh: internal error: %s\n", e.what());
    return kExitInternal;
  }
}
