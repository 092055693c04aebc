// What a stage's memory figure counts: this process's peak since the stage began, and
// with children, the processes it started too.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <memory>
#include <thread>

#include "common/memory.hpp"

using namespace grainmesh;

namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

// `mib` MiB, every page touched (so resident), then released.
void hold(std::size_t mib) {
  auto block = std::make_unique<char[]>(mib * kMiB);
  std::memset(block.get(), 1, mib * kMiB);
  REQUIRE(block[mib * kMiB - 1] == 1);
}

}  // namespace

TEST_CASE("a stage's memory is this process's peak during it, not before it", "[memory]") {
  double first = 0.0;
  {
    StageMemory stage;
    hold(300);
    first = stage.peak_mib();
  }
  CHECK(first >= 300.0);
  StageMemory second;  // the 300 MiB were freed before this stage began
  hold(20);
  CHECK(second.peak_mib() < first - 200.0);
  CHECK(second.peak_mib() == second.peak_mib());  // read once, kept
}

TEST_CASE("a stage with children counts the processes it started, summed with itself", "[memory]") {
  // A child holding 250 MiB for 0.6 s (several samples long); its exit code checked.
  auto child_holding_250_mib = [] {
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      auto block = std::make_unique<char[]>(250 * kMiB);
      std::memset(block.get(), 1, 250 * kMiB);
      std::this_thread::sleep_for(std::chrono::milliseconds(600));
      _exit(block[kMiB] == 1 ? 0 : 1);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
  };
  StageMemory with_children(true);
  child_holding_250_mib();
  CHECK(with_children.peak_mib() >= 250.0);
  StageMemory alone;
  child_holding_250_mib();
  CHECK(alone.peak_mib() < 250.0);
}
