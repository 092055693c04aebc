// grainmesh-tetgen: fills one closed surface with TetGen's library (Debian's libtet) and
// exits. A process of its own per surface, started fresh, so that a hung TetGen can be
// stopped and every fill starts from the same state (tetgen_fill.cpp runs it). Standard
// input and output are one socket (tetgen_protocol.hpp).
#define TETLIBRARY  // Debian's libtet is built so: TetGen throws its exit code instead of exiting
#include <tetgen.h>
#undef REAL

#include <sys/prctl.h>

#include <cmath>
#include <csignal>
#include <cstring>
#include <string>
#include <vector>

#include "grains3d/tetgen_protocol.hpp"

using namespace grainmesh::tetgen_protocol;

int main(int argc, char** argv) {
  // Dies with the thread that started it; gone already: nothing to do.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (argc > 1 && std::to_string(getppid()) != argv[1]) return 3;
  Request rq{};
  if (!read_all(0, &rq, sizeof rq)) return 2;
  std::string switches(rq.switches, '\0');
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(rq.points);
  in.pointlist = new double[3 * static_cast<std::size_t>(rq.points)];
  std::vector<int> corners(3 * static_cast<std::size_t>(rq.triangles));
  if (!read_all(0, switches.data(), switches.size()) || !read_all(0, in.pointlist, 3 * sizeof(double) * rq.points) ||
      !read_all(0, corners.data(), corners.size() * sizeof(int)))
    return 2;
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
    std::memcpy(f.polygonlist[0].vertexlist, &corners[3 * static_cast<std::size_t>(t)], 3 * sizeof(int));
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
  if (reply.status != 0) return write_all(1, &reply, sizeof reply) ? 0 : 2;
  reply.points = static_cast<std::uint32_t>(out.numberofpoints);
  reply.tets = static_cast<std::uint32_t>(out.numberoftetrahedra);
  const bool sent = write_all(1, &reply, sizeof reply) &&
                    write_all(1, out.pointlist, 3 * sizeof(double) * reply.points) &&
                    write_all(1, out.tetrahedronlist, 4 * sizeof(int) * reply.tets);
  return sent ? 0 : 2;
}
