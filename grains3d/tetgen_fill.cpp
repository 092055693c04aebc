#include "grains3d/tetgen_fill.hpp"

#include <signal.h>
#include <spawn.h>

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "common/process.hpp"
#include "grains3d/tetgen_protocol.hpp"
#include "mesh/tetmesh.hpp"

namespace grainmesh {

namespace {

// The enclosed volume of a closed surface turning outward (divergence theorem).
double enclosed_volume(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles) {
  double six_v = 0.0;
  for (const auto& t : triangles) six_v += dot(points[t[0]], cross(points[t[1]], points[t[2]]));
  return six_v / 6.0;
}

std::string smesh_text(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles) {
  std::string text = std::to_string(points.size()) + " 3 0 0\n";
  char buf[128];
  for (std::size_t k = 0; k < points.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%zu %.17g %.17g %.17g\n", k, points[k].x, points[k].y, points[k].z);
    text += buf;
  }
  text += std::to_string(triangles.size()) + " 0\n";
  for (const auto& t : triangles)
    text += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  return text + "0\n0\n";
}

// Keeps `text` as a file of its own in the system's temporary directory; its path.
std::filesystem::path keep(const std::string& text, const std::string& name) {
  std::string pattern = (std::filesystem::temp_directory_path() / ("grainmesh-" + name + "-XXXXXX.smesh")).string();
  const int fd = mkstemps(pattern.data(), 6);
  if (fd < 0) return {};
  const bool written = write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  close(fd);
  return written ? std::filesystem::path(pattern) : std::filesystem::path();
}

}  // namespace

namespace {

using namespace tetgen_protocol;

// The helper started with `socket` as its standard input and output; its pid, -1 when it
// could not be started.
pid_t spawn_helper(const std::string& helper, int socket) {
  // Spawned (vfork and exec: no copy of this process's page tables, whatever its size; a
  // fork per surface cost 20 ms at 1,000 grains). The helper ties itself to this process
  // (it dies with the thread that started it) and bounds its own call, so an interrupt,
  // which ends this process, ends it too.
  const std::string parent = std::to_string(getpid());
  const char* argv[] = {helper.c_str(), parent.c_str(), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, socket, STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, socket, STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);  // the helper takes the signals this process leaves to its thread
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, argv[0], &actions, &attributes, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  return spawned == 0 ? pid : -1;
}

// One try in a fresh helper: 0 and `fill` filled, TetGen's exit code, -1 when the helper
// died (an assertion) or gave no reply, -2 when its tetrahedra are not on the surface's
// points, or kChildOverBudget when it ran past `budget` seconds (it is then stopped).
int run_helper(const std::string& helper, const std::vector<Vec3>& points,
               const std::vector<std::array<int, 3>>& triangles, const std::string& switches, double budget,
               const Deadline& deadline, const std::string& what, TetgenFill& fill) {
  int fds[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
    throw IoError("cannot start TetGen's helper for " + what + " (socketpair failed)");
  const pid_t pid = spawn_helper(helper, fds[1]);
  close(fds[1]);
  const int fd = fds[0];
  if (pid < 0) {
    close(fd);
    throw IoError("cannot start TetGen's helper " + helper + " for " + what);
  }
  bool reaped = false;
  auto stop = [&] {
    if (!reaped) stop_child(pid, false);
    reaped = true;
  };
  auto finish = [&](int code) {
    stop();
    close(fd);
    return code;
  };
  const Request rq{static_cast<std::uint32_t>(points.size()), static_cast<std::uint32_t>(triangles.size()),
                   static_cast<std::uint32_t>(switches.size()), 2.0 * budget + 5.0};
  std::vector<double> xyz;
  for (const Vec3& p : points) xyz.insert(xyz.end(), {p.x, p.y, p.z});
  bool sent = write_all(fd, &rq, sizeof rq) && write_all(fd, switches.data(), switches.size()) &&
              write_all(fd, xyz.data(), xyz.size() * sizeof(double)) &&
              write_all(fd, triangles.data(), triangles.size() * sizeof(triangles[0]));
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  // Polled in short slices, so that the deadline and an interrupt are noticed at once.
  while (sent) {
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, 50);
    if (ready > 0) break;
    if (ready < 0 && errno != EINTR) sent = false;
    if (deadline.passed()) {
      finish(0);
      deadline.check("while TetGen filled " + what + " (it was stopped)");
    }
    if (std::chrono::duration<double>(Clock::now() - started).count() > budget) return finish(kChildOverBudget);
  }
  Reply reply{-1, 0, 0};
  if (!sent || !read_all(fd, &reply, sizeof reply)) {
    wait_if_interrupted();  // the interrupt killed it: no retry
    return finish(-1);      // it died (an assertion)
  }
  if (reply.status != 0) return finish(reply.status);
  std::vector<double> out_xyz(3 * static_cast<std::size_t>(reply.points));
  std::vector<std::array<int, 4>> tets(reply.tets);
  if (!read_all(fd, out_xyz.data(), out_xyz.size() * sizeof(double)) ||
      !read_all(fd, tets.data(), tets.size() * sizeof(tets[0])))
    return finish(-1);
  finish(0);
  // TetGen's numbering: its first points are the surface's, in the order given (-Y adds
  // none on the surface).
  if (reply.points < points.size()) return -2;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (Vec3{out_xyz[3 * k], out_xyz[3 * k + 1], out_xyz[3 * k + 2]} != points[k]) return -2;
  fill.points = points;
  for (std::size_t k = points.size(); k < reply.points; ++k)
    fill.points.push_back({out_xyz[3 * k], out_xyz[3 * k + 1], out_xyz[3 * k + 2]});
  for (auto tet : tets) {
    for (const int c : tet)
      if (c < 0 || c >= static_cast<int>(reply.points)) return -2;
    const auto& q = fill.points;
    if (tet_volume(q[tet[0]], q[tet[1]], q[tet[2]], q[tet[3]]) < 0.0) std::swap(tet[2], tet[3]);
    fill.tets.push_back(tet);
  }
  return 0;
}

}  // namespace

TetgenRunner::TetgenRunner() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path helper = self.parent_path() / "grainmesh-tetgen";
  if (ec || access(helper.c_str(), X_OK) != 0)
    throw GeometryError("TetGen's helper " + helper.string() + " is missing (make builds it beside grainmesh)");
  helper_ = helper.string();
}

double tetgen_budget(const TetgenOptions& o, double volume) {
  constexpr double kTetsPerBound = 1.3;  // TetGen makes about 1.3 tetrahedra per volume bound (grain_mesh_3d.hpp)
  return o.budget_seconds + o.budget_seconds_per_tet * kTetsPerBound * std::max(0.0, volume) / o.max_volume;
}

TetgenFill TetgenRunner::fill(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                              const TetgenOptions& o, const std::string& what) const {
  o.deadline.check("before TetGen filled " + what);
  const double budget = tetgen_budget(o, enclosed_volume(points, triangles));
  TetgenFill fill;
  std::string tried;
  for (const std::string& order : o.orders) {
    char switches[128];
    std::snprintf(switches, sizeof switches, "pYzQq%.6g/%.6ga%.6gO7/7%s", o.radius_edge, o.min_dihedral_deg,
                  o.max_volume, order.c_str());
    ++fill.tries;
    const int code = run_helper(helper_, points, triangles, switches, budget, o.deadline, what, fill);
    if (code == 0) {
      fill.switches = switches;
      return fill;
    }
    fill.points.clear(), fill.tets.clear();
    tried += (tried.empty() ? "-" : ", -") + std::string(switches) +
             (code == kChildOverBudget ? " did not finish in " + to_text(budget, 3) + " s"
              : code == -1             ? " ended TetGen (an assertion)"
              : code == -2             ? " gave tetrahedra not on the surface's points"
                                       : " failed (TetGen's code " + std::to_string(code) + ")");
  }
  const std::filesystem::path kept = keep(smesh_text(points, triangles), "tetgen");
  throw GeometryError(
      "TetGen could not fill " + what + ": " + tried + "; its input is kept as " +
      (kept.empty() ? std::string("(it could not be kept)") : kept.string()) +
      " (report it); a slightly different mesh size (mesh.tets_per_grain) or seed gives other surfaces");
}

}  // namespace grainmesh
