#include "export/gmsh_file.hpp"

#include <algorithm>
#include <limits>
#include <map>

#include "common/number_text.hpp"
#include "common/text_file.hpp"

namespace grainmesh {

namespace {

// Gmsh's element types: 2-node line, 3-node triangle, 4-node tetrahedron.
int element_type(int corners) { return corners == 2 ? 1 : corners == 3 ? 2 : 4; }


// An elementary entity: its points' bounding box and its physical groups.
struct Entity {
  int dim = 0, tag = 0;
  std::vector<int> physical;
  std::vector<int> points;  // the nodes classified on it
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3 hi{-lo.x, -lo.y, -lo.z};
  void extend(const Vec3& p) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
};

void write_entities(FileText& out, const ElementMesh& m, const std::vector<Entity>& entities) {
  std::array<int, 4> count{};
  for (const Entity& e : entities) ++count[e.dim];
  out << "$Entities\n" << count[0] << " " << count[1] << " " << count[2] << " " << count[3] << "\n";
  for (int dim = 1; dim <= m.dimensions; ++dim)
    for (const Entity& e : entities) {
      if (e.dim != dim) continue;
      const bool empty = e.lo.x > e.hi.x;
      const Vec3 lo = empty ? m.cell.lo : e.lo, hi = empty ? m.cell.hi : e.hi;
      out << e.tag << " " << lo.x << " " << lo.y << " " << lo.z << " " << hi.x << " " << hi.y << " " << hi.z << " "
          << e.physical.size();
      for (int p : e.physical) out << " " << p;
      out << " 0\n";  // no bounding entities
    }
  out << "$EndEntities\n";
}

// The nodes entity by entity, tagged 1.. in the order they are written (as Gmsh numbers
// them, and as readers that take a node's rank for its tag expect); returns the tags.
std::vector<int> write_nodes(FileText& out, const ElementMesh& m, const std::vector<Entity>& entities) {
  std::size_t blocks = 0;
  for (const Entity& e : entities) blocks += e.points.empty() ? 0 : 1;
  out << "$Nodes\n" << blocks << " " << m.points.size() << " 1 " << m.points.size() << "\n";
  std::vector<int> tag(m.points.size(), 0);
  int next = 0;
  for (const Entity& e : entities) {
    if (e.points.empty()) continue;
    out << e.dim << " " << e.tag << " 0 " << e.points.size() << "\n";
    for (int p : e.points) out << (tag[p] = ++next) << "\n";
    for (int p : e.points) out << m.points[p].x << " " << m.points[p].y << " " << m.points[p].z << "\n";
  }
  out << "$EndNodes\n";
  return tag;
}

void write_periodic(FileText& out, const ElementMesh& m, const std::vector<int>& tag) {
  out << "$Periodic\n" << m.dimensions << "\n";
  for (int axis = 0; axis < m.dimensions; ++axis) {
    // The high side (slave) is the low side (master) translated across the cell.
    out << m.dimensions - 1 << " " << 2 * axis + 2 << " " << 2 * axis + 1 << "\n16";
    for (int row = 0; row < 4; ++row)
      for (int col = 0; col < 4; ++col)
        out << " " << (col == 3 && row == axis ? m.cell.hi[axis] - m.cell.lo[axis] : row == col ? 1.0 : 0.0);
    out << "\n" << m.pairs.axis[axis].size() << "\n";
    for (const auto& [low, high] : m.pairs.axis[axis]) out << tag[high] << " " << tag[low] << "\n";
  }
  out << "$EndPeriodic\n";
}

}  // namespace

void write_gmsh(const std::filesystem::path& file, const ElementMesh& m) {
  const std::vector<int> grains = grains_of(m);
  const int d = m.dimensions, phases = static_cast<int>(m.phases.size());
  // Entities: the sides (dimension d - 1, tags 1..2d), the grains (dimension d, tags 1..).
  std::vector<Entity> entities;
  for (int s = 0; s < m.sides(); ++s)
    entities.push_back({.dim = d - 1, .tag = s + 1, .physical = {s + 1}, .points = {}});
  std::map<int, int> grain_entity;  // grain -> index in entities
  for (std::size_t g = 0; g < grains.size(); ++g) {
    grain_entity[grains[g]] = static_cast<int>(entities.size());
    entities.push_back({.dim = d, .tag = static_cast<int>(g) + 1, .physical = {}, .points = {}});
  }
  std::vector<std::vector<int>> elements_of(grains.size());
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    Entity& entity = entities[grain_entity[m.grain[e]]];
    if (entity.physical.empty())
      entity.physical = {m.phase[e] + 1, phases + entity.tag};  // its phase, itself
    elements_of[entity.tag - 1].push_back(static_cast<int>(e));
  }
  // Each node classified once: on the first side it lies on, else in the first grain
  // whose element has it.
  const std::vector<std::vector<int>> on_side = side_points(m);
  std::vector<int> entity_of(m.points.size(), -1);
  for (int s = 0; s < m.sides(); ++s)
    for (int p : on_side[s])
      if (entity_of[p] < 0) entity_of[p] = s;
  for (std::size_t e = 0; e < m.elements.size(); ++e)
    for (int k = 0; k < m.corners(); ++k)
      if (entity_of[m.elements[e][k]] < 0) entity_of[m.elements[e][k]] = grain_entity[m.grain[e]];
  for (std::size_t p = 0; p < m.points.size(); ++p) {
    Entity& e = entities[entity_of[p] < 0 ? m.sides() : entity_of[p]];
    e.points.push_back(static_cast<int>(p));
  }
  for (std::size_t e = 0; e < m.elements.size(); ++e)
    for (int k = 0; k < m.corners(); ++k) entities[grain_entity[m.grain[e]]].extend(m.points[m.elements[e][k]]);
  const std::vector<std::vector<std::array<int, 3>>> facets = side_facets(m);
  for (int s = 0; s < m.sides(); ++s)
    for (int p : on_side[s]) entities[s].extend(m.points[p]);

  FileText out;
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n" << m.sides() + phases + grains.size() << "\n";
  for (int s = 0; s < m.sides(); ++s) out << d - 1 << " " << s + 1 << " \"" << side_name(m, s) << "\"\n";
  for (int p = 0; p < phases; ++p) out << d << " " << p + 1 << " \"" << m.phases[p].name << "\"\n";
  for (std::size_t g = 0; g < grains.size(); ++g)
    out << d << " " << phases + 1 + static_cast<int>(g) << " \"grain_" << grains[g] << "\"\n";
  out << "$EndPhysicalNames\n";
  write_entities(out, m, entities);
  const std::vector<int> tag = write_nodes(out, m, entities);
  std::size_t facet_count = 0;
  for (const auto& f : facets) facet_count += f.size();
  const std::size_t total = m.elements.size() + facet_count;
  out << "$Elements\n" << grains.size() + m.sides() << " " << total << " 1 " << total << "\n";
  // The grains' elements tagged by their index + 1, then the sides' facets.
  for (std::size_t g = 0; g < grains.size(); ++g) {
    out << d << " " << static_cast<int>(g) + 1 << " " << element_type(m.corners()) << " " << elements_of[g].size()
        << "\n";
    for (int e : elements_of[g]) {
      out << e + 1;
      for (int k = 0; k < m.corners(); ++k) out << " " << tag[m.elements[e][k]];
      out << "\n";
    }
  }
  std::size_t facet_tag = m.elements.size();
  for (int s = 0; s < m.sides(); ++s) {
    out << d - 1 << " " << s + 1 << " " << element_type(d) << " " << facets[s].size() << "\n";
    for (const auto& f : facets[s]) {
      out << ++facet_tag;
      for (int k = 0; k < d; ++k) out << " " << tag[f[k]];
      out << "\n";
    }
  }
  out << "$EndElements\n";
  if (m.periodic) write_periodic(out, m, tag);
  write_text_file(file, out.s);
}

}  // namespace grainmesh
