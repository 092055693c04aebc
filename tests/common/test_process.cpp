// Child processes: the environment they are given, their exit codes, and the watcher
// that ends them.
#include <unistd.h>

#include <chrono>
#include <cstdlib>

#include <catch2/catch.hpp>

#include "common/allocator.hpp"
#include "common/process.hpp"
#include "common/text_file.hpp"
#include "export/foam_solver.hpp"
#include "helpers.hpp"

using namespace grainmesh;

TEST_CASE("a child gets the environment it is given on top of this process's", "[process]") {
  test::ScratchDir dir("process-env");
  setenv("GRAINMESH_TEST_REPLACED", "outer", 1);
  setenv("GRAINMESH_TEST_KEPT", "kept", 1);
  const int code = run_child({"sh", "-c", "echo \"$GRAINMESH_TEST_REPLACED $GRAINMESH_TEST_ADDED $GRAINMESH_TEST_KEPT\""},
                             dir.path(), dir / "log", Deadline(), "sh",
                             {"GRAINMESH_TEST_REPLACED=inner", "GRAINMESH_TEST_ADDED=added"});
  CHECK(code == 0);
  CHECK(read_text_file(dir / "log", "the log") == "inner added kept\n");
  // This process's own environment is left as it was.
  CHECK(std::string(std::getenv("GRAINMESH_TEST_REPLACED")) == "outer");
  CHECK(std::getenv("GRAINMESH_TEST_ADDED") == nullptr);
  unsetenv("GRAINMESH_TEST_REPLACED");
  unsetenv("GRAINMESH_TEST_KEPT");
}

TEST_CASE("a child's exit code is returned, and a watcher that says stop kills it", "[process]") {
  test::ScratchDir dir("process-exit");
  CHECK(run_child({"sh", "-c", "exit 3"}, dir.path(), dir / "log", Deadline(), "sh") == 3);
  CHECK(run_child({"grainmesh-no-such-program"}, dir.path(), dir / "log", Deadline(), "nothing") == 127);
  const auto start = std::chrono::steady_clock::now();
  const int killed = run_child({"sh", "-c", "echo stop; exec sleep 30"}, dir.path(), dir / "log", Deadline(), "sh", {},
                               [](std::string_view text) { return text.find("stop") != std::string_view::npos; });
  CHECK(killed == 128 + 9);
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 10.0);
}

TEST_CASE("OpenFOAM runs with the Debian package's directory and glibc told to keep freed memory", "[process][foam]") {
  const char* had_project = std::getenv("WM_PROJECT_DIR");
  const std::string project = had_project != nullptr ? had_project : "";
  unsetenv("WM_PROJECT_DIR");
  unsetenv("GLIBC_TUNABLES");
  const std::string tunables = "GLIBC_TUNABLES=" + malloc_tunables();
  CHECK(tunables == "GLIBC_TUNABLES=glibc.malloc.mmap_threshold=268435456:glibc.malloc.trim_threshold=1073741824");
  // Run as root, Open MPI's mpirun (solve.processes) needs to be told that it may.
  const std::vector<std::string> as_root =
      geteuid() == 0 ? std::vector<std::string>{"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"}
                     : std::vector<std::string>{};
  auto with_root = [&](std::vector<std::string> env) {
    env.insert(env.end(), as_root.begin(), as_root.end());
    return env;
  };
  CHECK(foam_environment() == with_root({"WM_PROJECT_DIR=/usr/share/openfoam", tunables}));
  // A user's own settings are kept: their directory, their tunables after ours (the last wins).
  setenv("WM_PROJECT_DIR", "/opt/openfoam", 1);
  setenv("GLIBC_TUNABLES", "glibc.malloc.tcache_count=0", 1);
  CHECK(foam_environment() == with_root({"WM_PROJECT_DIR=/opt/openfoam", tunables + ":glibc.malloc.tcache_count=0"}));
  unsetenv("GLIBC_TUNABLES");
  if (had_project != nullptr)
    setenv("WM_PROJECT_DIR", project.c_str(), 1);
  else
    unsetenv("WM_PROJECT_DIR");
}

TEST_CASE("a child over its budget is stopped: its whole run, or a stretch without output", "[process]") {
  test::ScratchDir dir("process-budget");
  auto timed = [&](const std::string& script, const ChildBudget& budget) {
    const auto start = std::chrono::steady_clock::now();
    const int code = run_child({"sh", "-c", script}, dir.path(), dir / "log", Deadline(), "sh", {}, {}, budget);
    return std::pair{code, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  };
  // Over its whole budget.
  const auto [whole, whole_took] = timed("exec sleep 30", {.seconds = 0.5});
  CHECK(whole == kChildOverBudget);
  CHECK(whole_took < 5.0);
  // Writing now and then keeps it alive past its idle budget; falling silent ends it.
  const auto [idle, idle_took] =
      timed("for i in 1 2 3 4 5 6; do echo $i; sleep 0.2; done; exec sleep 30", {.idle_seconds = 0.6});
  CHECK(idle == kChildOverBudget);
  CHECK(idle_took > 1.0);
  CHECK(idle_took < 6.0);
  CHECK(read_text_file(dir / "log", "the log") == "1\n2\n3\n4\n5\n6\n");
  // Within its budget: its own exit code.
  CHECK(timed("exit 4", {.seconds = 10.0, .idle_seconds = 10.0}).first == 4);
}
