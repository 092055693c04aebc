// What tetgen_fill.cpp and its helper program grainmesh-tetgen (tetgen_helper.cpp) say to
// each other over the helper's standard input and output: one request, one reply.
#pragma once

#include <cerrno>
#include <cstddef>
#include <cstdint>

#include <sys/socket.h>
#include <unistd.h>

namespace grainmesh::tetgen_protocol {

// The counts, the helper's own time bound (a hung TetGen ends itself when its parent has
// gone), then the switches, the points' coordinates and the triangles' corners.
struct Request {
  std::uint32_t points, triangles, switches;
  double alarm_seconds;
};
// TetGen's exit code (0: done; then the counts, the points' coordinates and the
// tetrahedra's corners).
struct Reply {
  std::int32_t status;
  std::uint32_t points, tets;
};

inline bool write_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t k = send(fd, p, n, MSG_NOSIGNAL);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k, n -= static_cast<std::size_t>(k);
  }
  return true;
}

inline bool read_all(int fd, void* data, std::size_t n) {
  char* p = static_cast<char*>(data);
  while (n > 0) {
    const ssize_t k = read(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k, n -= static_cast<std::size_t>(k);
  }
  return true;
}

}  // namespace grainmesh::tetgen_protocol
