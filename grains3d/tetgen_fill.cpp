#include "grains3d/tetgen_fill.hpp"

#define TETLIBRARY  // Debian's libtet is built so: TetGen throws its exit code instead of exiting
#include <tetgen.h>
#undef REAL

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"
#include "common/process.hpp"
#include "mesh/tetmesh.hpp"

namespace grainmesh {

namespace {

// What a worker is sent: the counts, its own time bound (a hung TetGen call in a worker
// whose parent has gone ends itself), then the switches, the points' coordinates and the
// triangles' corners.
struct Request {
  std::uint32_t points, triangles, switches;
  double alarm_seconds;
};
// What it sends back: TetGen's exit code (0: done; then the counts, the points'
// coordinates and the tetrahedra's corners).
struct Reply {
  std::int32_t status;
  std::uint32_t points, tets;
};

bool write_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t k = send(fd, p, n, MSG_NOSIGNAL);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k, n -= static_cast<std::size_t>(k);
  }
  return true;
}

bool read_all(int fd, void* data, std::size_t n) {
  char* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t k = read(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k, n -= static_cast<std::size_t>(k);
  }
  return true;
}

// One request filled by TetGen in this (worker) process; false when the parent has gone.
bool serve_one(int fd) {
  Request rq{};
  if (!read_all(fd, &rq, sizeof rq)) return false;
  std::string switches(rq.switches, '\0');
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(rq.points);
  in.pointlist = new double[3 * rq.points];
  std::vector<int> corners(3 * static_cast<std::size_t>(rq.triangles));
  if (!read_all(fd, switches.data(), switches.size()) || !read_all(fd, in.pointlist, 3 * sizeof(double) * rq.points) ||
      !read_all(fd, corners.data(), corners.size() * sizeof(int)))
    return false;
  in.numberoffacets = static_cast<int>(rq.triangles);
  in.facetlist = new tetgenio::facet[rq.triangles];
  for (std::uint32_t t = 0; t < rq.triangles; ++t) {
    tetgenio::facet& f = in.facetlist[t];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3];
    std::memcpy(f.polygonlist[0].vertexlist, &corners[3 * t], 3 * sizeof(int));
  }
  alarm(static_cast<unsigned>(std::ceil(rq.alarm_seconds)));
  Reply reply{0, 0, 0};
  try {
    tetrahedralize(switches.data(), &in, &out);
  } catch (int code) {
    reply.status = code == 0 ? -1 : code;
  } catch (...) {
    reply.status = -1;
  }
  alarm(0);
  if (reply.status != 0) return write_all(fd, &reply, sizeof reply);
  reply.points = static_cast<std::uint32_t>(out.numberofpoints);
  reply.tets = static_cast<std::uint32_t>(out.numberoftetrahedra);
  return write_all(fd, &reply, sizeof reply) && write_all(fd, out.pointlist, 3 * sizeof(double) * reply.points) &&
         write_all(fd, out.tetrahedronlist, 4 * sizeof(int) * reply.tets);
}

// A worker's life: requests served until the parent closes its end or goes.
[[noreturn]] void serve(int fd) {
  // TetGen's few words (-Q keeps most back) go nowhere: the parent reports what failed.
  const int null = open("/dev/null", O_WRONLY);
  if (null >= 0) dup2(null, STDOUT_FILENO), dup2(null, STDERR_FILENO);
  while (serve_one(fd)) {
  }
  _exit(0);
}

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

struct TetgenWorkers::Worker {
  int fd = -1;
  std::unique_ptr<RegisteredChild> child;

  Worker() {
    int fds[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
      throw IoError("cannot start a TetGen worker (socketpair failed)");
    std::fflush(nullptr);
    child = std::make_unique<RegisteredChild>();
    if (child->pid() == 0) {
      close(fds[0]);
      // Only its own end stays open, so that the parent's going (its ends closed) ends it.
      if (dup2(fds[1], 3) < 0) _exit(1);
      close_range(4, ~0U, 0);
      serve(3);
    }
    close(fds[1]);
    if (child->pid() < 0) {
      close(fds[0]);
      throw IoError("cannot start a TetGen worker (fork failed)");
    }
    fd = fds[0];
  }
  ~Worker() {
    stop();
    close(fd);
  }
  // Kills and reaps it, once (a reaped pid may be another process's soon).
  void stop() {
    if (!reaped) stop_child(child->pid(), false);
    reaped = true;
  }
  bool reaped = false;
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  // One try: 0 and `fill` filled, a TetGen exit code, or kChildOverBudget when the worker
  // ran past `budget` seconds (it is then dead, as after any failure: the caller replaces it).
  int run(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
          const std::string& switches, double budget, const Deadline& deadline, const std::string& what,
          TetgenFill& fill) {
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
        stop();
        deadline.check("while TetGen filled " + what + " (it was stopped)");
      }
      if (std::chrono::duration<double>(Clock::now() - started).count() > budget) return kChildOverBudget;
    }
    Reply reply{-1, 0, 0};
    if (!sent || !read_all(fd, &reply, sizeof reply)) {
      wait_if_interrupted();  // the interrupt killed it: no retry
      return -1;              // it died (an assertion)
    }
    if (reply.status != 0) return reply.status;
    std::vector<double> out_xyz(3 * static_cast<std::size_t>(reply.points));
    std::vector<std::array<int, 4>> tets(reply.tets);
    if (!read_all(fd, out_xyz.data(), out_xyz.size() * sizeof(double)) ||
        !read_all(fd, tets.data(), tets.size() * sizeof(tets[0])))
      return -1;
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
};

TetgenWorkers::TetgenWorkers() = default;
TetgenWorkers::~TetgenWorkers() = default;

double tetgen_budget(const TetgenOptions& o, double volume) {
  constexpr double kTetsPerBound = 1.3;  // TetGen makes about 1.3 tetrahedra per volume bound (grain_mesh_3d.hpp)
  return o.budget_seconds + o.budget_seconds_per_tet * kTetsPerBound * std::max(0.0, volume) / o.max_volume;
}

TetgenFill TetgenWorkers::fill(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
                               const TetgenOptions& o, const std::string& what) {
  o.deadline.check("before TetGen filled " + what);
  const double budget = tetgen_budget(o, enclosed_volume(points, triangles));
  std::unique_ptr<Worker> worker;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!idle_.empty()) worker = std::move(idle_.back()), idle_.pop_back();
  }
  TetgenFill fill;
  std::string tried;
  for (const std::string& order : o.orders) {
    char switches[128];
    std::snprintf(switches, sizeof switches, "pYzQq%.6g/%.6ga%.6gO7/7%s", o.radius_edge, o.min_dihedral_deg,
                  o.max_volume, order.c_str());
    ++fill.tries;
    if (!worker) worker = std::make_unique<Worker>();
    const int code = worker->run(points, triangles, switches, budget, o.deadline, what, fill);
    if (code == 0) {
      fill.switches = switches;
      const std::lock_guard<std::mutex> lock(mutex_);
      idle_.push_back(std::move(worker));
      return fill;
    }
    worker.reset();  // killed: a failed TetGen leaves nothing to trust
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
