#include "export/pin_translation.hpp"

#include <cstdlib>

#include "export/foam_geometry.hpp"
#include "export/polymesh.hpp"

namespace grainmesh {

namespace {

// Cell c's centre as OpenFOAM computes it: pyramids from the mean of its face centres.
Vec3 cell_centre(const PolyMesh& pm, int c) {
  std::vector<std::pair<FoamFace, double>> faces;  // each face, and +1 owned / -1 neighboured
  Vec3 estimate;
  for (int f = 0; f < pm.faces(); ++f) {
    const bool owned = pm.owner[f] == c, neighboured = f < pm.internal_faces() && pm.neighbour[f] == c;
    if (!owned && !neighboured) continue;
    faces.push_back({foam_face(pm, f), owned ? 1.0 : -1.0});
    estimate += faces.back().first.centre;
  }
  estimate = estimate / static_cast<double>(faces.size());
  Vec3 centre;
  double volume = 0.0;
  for (const auto& [face, sign] : faces) {
    const double v3 = sign * dot(face.area, face.centre - estimate);
    centre += v3 * (0.75 * face.centre + 0.25 * estimate);
    volume += v3;
  }
  return centre / volume;
}

// Where the pinned face's displacement is fixed: the foot of the perpendicular from its
// cell's centre to the face's plane. OpenFOAM's gradient through a fixedValue face is
// (D_face - D_cell) / (n . d) with no non-orthogonal correction, which is exact for a
// linear field only at that point; at the face's centre a face whose cell does not sit
// square on it would take a wrong force even on one material (measured: 6e-5 of C11 on
// tetrahedra, a 0.4 % residual stress beside it in 2D).
Vec3 pinned_point(const PolyMesh& pm, int f) {
  const FoamFace face = foam_face(pm, f);
  const Vec3 n = face.area / norm(face.area), centre = cell_centre(pm, pm.owner[f]);
  return centre + dot(face.centre - centre, n) * n;
}

// Moves face `from` to position `to` (from < to, both in one patch): the faces between
// move down by one. The owner list and the points' list follow.
void move_face_to(PolyMesh& pm, int from, int to) {
  const std::vector<int> points(pm.face_points.begin() + pm.face_start[from], pm.face_points.begin() + pm.face_start[from + 1]);
  const int owner = pm.owner[from];
  const int n = static_cast<int>(points.size());
  // The points of faces from + 1 .. to slide down over face `from`'s; its own go after them.
  auto first = pm.face_points.begin() + pm.face_start[from];
  auto last = pm.face_points.begin() + pm.face_start[to + 1];
  std::rotate(first, first + n, last);
  for (int f = from; f < to; ++f) {
    pm.face_start[f + 1] = pm.face_start[f] + (pm.face_start[f + 2] - pm.face_start[f + 1]);
    pm.owner[f] = pm.owner[f + 1];
  }
  pm.owner[to] = owner;
}

}  // namespace

bool is_pin_patch(const PolyMesh::Patch& p) { return p.name == kPinPatchLow || p.name == kPinPatchHigh; }

std::string pin_patch_of(const std::string& side) {
  if (side == "left") return kPinPatchLow;
  if (side == "right") return kPinPatchHigh;
  return {};
}

void pin_translation(PolyMesh& pm, const std::vector<int>& phase, Vec3 origin) {
  const int left = patch_index(pm, "left"), right = patch_index(pm, "right");
  if (left < 0 || right < 0 || pm.patches[left].type != "cyclic" || pm.patches[left].size < 2) return;
  const int size = pm.patches[left].size;
  // Cells with a neighbour of another phase, across internal and cyclic faces.
  std::vector<char> at_interface(static_cast<std::size_t>(pm.cells), 0);
  auto mark = [&](int a, int b) {
    if (phase[a] != phase[b]) at_interface[a] = at_interface[b] = 1;
  };
  for (int f = 0; f < pm.internal_faces(); ++f) mark(pm.owner[f], pm.neighbour[f]);
  for (const PolyMesh::Patch& p : pm.patches) {
    if (p.type != "cyclic") continue;
    const PolyMesh::Patch& other = pm.patches[patch_index(pm, p.neighbour_patch)];
    for (int k = 0; k < p.size; ++k) mark(pm.owner[p.start + k], pm.owner[other.start + k]);
  }
  // From the middle of the side outwards: the first pair inside one phase, of two cells.
  int chosen = size / 2;
  for (int step = 0; step < size; ++step) {
    const int k = size / 2 + (step % 2 == 0 ? step / 2 : -(step + 1) / 2);
    if (k < 0 || k >= size) continue;
    const int a = pm.owner[pm.patches[left].start + k], b = pm.owner[pm.patches[right].start + k];
    if (a != b && !at_interface[a] && !at_interface[b]) {
      chosen = k;
      break;
    }
  }
  // The pair to the end of both patches (so that face k of one still pairs with face k of
  // the other), then cut off as the pin patches.
  for (const int p : {left, right}) move_face_to(pm, pm.patches[p].start + chosen, pm.patches[p].start + size - 1);
  std::vector<PolyMesh::Patch> patches;
  for (const PolyMesh::Patch& p : pm.patches) {
    if (&p != &pm.patches[left] && &p != &pm.patches[right]) {
      patches.push_back(p);
      continue;
    }
    PolyMesh::Patch cut = p;
    cut.size -= 1;
    patches.push_back(cut);
    const int face = p.start + p.size - 1;
    patches.push_back({.name = &p == &pm.patches[left] ? kPinPatchLow : kPinPatchHigh,
                       .type = "patch",
                       .start = face,
                       .size = 1,
                       .neighbour_patch = {},
                       .separation = {},
                       .at = pinned_point(pm, face) - origin});
  }
  pm.patches = std::move(patches);
}

}  // namespace grainmesh
