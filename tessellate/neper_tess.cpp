#include "tessellate/neper_tess.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "common/errors.hpp"
#include "common/text_file.hpp"

namespace grainmesh {

namespace {

// The file's words in order, with what went wrong named after the file.
class Words {
 public:
  Words(std::string text, std::filesystem::path file) : text_(std::move(text)), file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& what) const { throw GeometryError(file_.string() + ": " + what); }
  // The next word ("" at the end).
  std::string next() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    const std::size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    return text_.substr(start, at_ - start);
  }
  std::string peek() {
    const std::size_t keep = at_;
    std::string w = next();
    at_ = keep;
    return w;
  }
  void expect(const std::string& word, const std::string& where) {
    const std::string w = next();
    if (w != word) fail("expected " + word + " " + where + ", found '" + w + "'");
  }
  double number(const std::string& what) {
    const std::string w = next();
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (w.empty() || *end != '\0') fail("expected a number (" + what + "), found '" + w + "'");
    return v;
  }
  int integer(const std::string& what, long lo = std::numeric_limits<int>::min(),
              long hi = std::numeric_limits<int>::max()) {
    const std::string w = next();
    char* end = nullptr;
    const long v = std::strtol(w.c_str(), &end, 10);
    if (w.empty() || *end != '\0') fail("expected an integer (" + what + "), found '" + w + "'");
    if (v < lo || v > hi)
      fail(what + " " + w + " out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return static_cast<int>(v);
  }
  // Skips words up to the next that starts with `mark` ("*": any section, "**": a field).
  void skip_to(const std::string& mark) {
    while (!peek().empty() && peek().rfind(mark, 0) != 0) next();
  }

 private:
  std::string text_;
  std::filesystem::path file_;
  std::size_t at_ = 0;
};

// An empty cell (Neper writes one for a seed whose cell misses the domain).
constexpr const char* kEmptyCell =
    " is empty (a cell whose seed lies outside the domain?): grainmesh reads tessellations without empty cells";

Vec3 point(Words& w, const std::string& what) {
  Vec3 p;
  p.x = w.number(what + " x");
  p.y = w.number(what + " y");
  p.z = w.number(what + " z");
  return p;
}

// ***tess, **format 3.4 (or 3.5), **general DIM standard|periodic: the dimension and
// whether the cells are periodic.
int read_header(Words& w, bool& periodic) {
  if (w.next() != "***tess") w.fail("not a Neper tessellation (it does not start with ***tess)");
  w.expect("**format", "after ***tess");
  const std::string format = w.next();
  if (format != "3.4" && format != "3.5")
    w.fail("format " + format + " is not read (grainmesh reads the formats Neper 4 writes, " + kNeperFormats + ")");
  w.expect("**general", "after the format");
  const int dim = w.integer("dimension");
  if (dim != 2 && dim != 3) w.fail("a " + std::to_string(dim) + "D tessellation: grainmesh reads 2D and 3D ones");
  const std::string type = w.next();
  if (type != "standard" && type != "periodic")
    w.fail("a tessellation of type '" + type + "' (grainmesh reads standard and periodic ones)");
  periodic = type == "periodic";
  return dim;
}

// Each entry's id must be its rank + 1.
void check_id(Words& w, int id, int k, const std::string& what) {
  if (id != k + 1) w.fail(what + " " + std::to_string(k + 1) + " has id " + std::to_string(id));
}

void read_cells(Words& w, NeperTess& t) {
  const int n = w.integer("the number of cells", 1);
  t.seeds.assign(n, Vec3{});
  bool seeds = false;
  for (std::string s = w.peek(); s.rfind("*", 0) == 0 && s.rfind("**", 0) != 0; s = w.peek()) {
    w.next();
    if (s == "*group") {
      t.groups.resize(n);
      for (int& g : t.groups) g = w.integer("a cell's group");
      continue;
    }
    if (s != "*seed") {
      w.skip_to("*");  // *id, *ori, *crysym, ...: not needed
      continue;
    }
    for (int k = 0; k < n; ++k) {
      check_id(w, w.integer("seed id"), k, "seed");
      t.seeds[k] = point(w, "seed");
      w.number("seed weight");
    }
    seeds = true;
  }
  if (!seeds) w.fail("**cell has no *seed");
}

// **periodicity: *general (the periodic axes, their periods), then the secondary seeds,
// vertices, edges and (3D) faces, each with its primary and lattice shift. The vertices'
// images are kept; the rest is checked for its layout only.
void read_periodicity(Words& w, NeperTess& t) {
  w.expect("*general", "after **periodicity");
  for (int a = 0; a < 3; ++a) t.periodic_axes[a] = w.integer("a periodicity flag", 0, 1) == 1;
  for (int a = 0; a < 3; ++a) t.period[a] = w.number("a periodicity distance");
  const int vertices = static_cast<int>(t.vertices.size());
  for (std::string s = w.peek(); s.rfind("*", 0) == 0 && s.rfind("**", 0) != 0; s = w.peek()) {
    w.next();
    const int n = w.integer("the number of periodic " + s.substr(1) + " entries", 0);
    const int extra = s == "*edge" || s == "*face" ? 1 : 0;  // their orientation
    for (int k = 0; k < n; ++k) {
      NeperTess::Image image;
      const bool vertex = s == "*vertex";
      image.vertex =
          w.integer("a secondary " + s.substr(1), 1, vertex ? vertices : std::numeric_limits<int>::max()) - 1;
      image.primary = w.integer("a primary " + s.substr(1), 1, vertex ? vertices : std::numeric_limits<int>::max()) - 1;
      for (int& c : image.shift) c = w.integer("a periodic shift", -1, 1);
      for (int e = 0; e < extra; ++e) w.integer("an orientation");
      if (vertex) t.vertex_images.push_back(image);
    }
  }
  t.periodic = true;
}

void read_field(Words& w, NeperTess& t, const std::string& field) {
  const auto count = [&](const std::string& what) { return w.integer("the number of " + what, 0); };
  if (field == "**vertex") {
    const int n = count("vertices");
    for (int k = 0; k < n; ++k) {
      check_id(w, w.integer("vertex id"), k, "vertex");
      t.vertices.push_back(point(w, "vertex"));
      w.integer("vertex state");
    }
  } else if (field == "**edge") {
    const int n = count("edges");
    for (int k = 0; k < n * 4; ++k) w.integer("an edge's entry");  // id v1 v2 state: the faces give the rings
  } else if (field == "**face") {
    const int n = count("faces"), vertices = static_cast<int>(t.vertices.size());
    for (int k = 0; k < n; ++k) {
      check_id(w, w.integer("face id"), k, "face");
      const int corners = w.integer("a face's vertex count", 0, vertices);
      if (corners == 0) w.fail("face " + std::to_string(k + 1) + kEmptyCell);
      if (corners < 3) w.fail("face " + std::to_string(k + 1) + " has " + std::to_string(corners) + " vertices");
      std::vector<int> ring(corners);
      for (int& v : ring) v = w.integer("a face's vertex", 1, vertices) - 1;
      const int edges = w.integer("a face's edge count", 3);
      for (int e = 0; e < edges; ++e) w.integer("a face's edge");
      for (int e = 0; e < 4; ++e) w.number("a face's equation");
      w.integer("face state");
      w.integer("face point");
      point(w, "face point");
      t.faces.push_back(std::move(ring));
    }
  } else if (field == "**polyhedron") {
    const int n = count("polyhedra"), faces = static_cast<int>(t.faces.size());
    for (int k = 0; k < n; ++k) {
      check_id(w, w.integer("polyhedron id"), k, "polyhedron");
      const int sides = w.integer("a polyhedron's face count", 0, faces);
      if (sides == 0) w.fail("polyhedron " + std::to_string(k + 1) + kEmptyCell);
      if (sides < 4) w.fail("polyhedron " + std::to_string(k + 1) + " has " + std::to_string(sides) + " faces");
      std::vector<int> list(sides);
      for (int& f : list) {
        f = w.integer("a polyhedron's face", -faces, faces);
        if (f == 0) w.fail("a polyhedron's face 0");
      }
      t.polyhedra.push_back(std::move(list));
    }
  } else if (field == "**domain") {
    w.expect("*general", "after **domain");
    t.domain_type = w.next();
    w.expect("*vertex", "after the domain's type");
    const int n = count("domain vertices");
    t.domain = Box3{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
    for (int k = 0; k < n; ++k) {
      check_id(w, w.integer("domain vertex id"), k, "domain vertex");
      const Vec3 p = point(w, "domain vertex");
      t.domain_vertices.push_back(p);
      for (int a = 0; a < 3; ++a) {
        t.domain.lo[a] = std::min(t.domain.lo[a], p[a]);
        t.domain.hi[a] = std::max(t.domain.hi[a], p[a]);
      }
      w.next();  // label
      const int m = w.integer("a domain vertex's tessellation vertices", 0);
      for (int j = 0; j < m; ++j) w.integer("a domain vertex's tessellation vertex");
    }
    w.skip_to("**");  // *edge, *face
  } else if (field == "**periodicity" || field == "**periodic") {
    read_periodicity(w, t);
  } else {
    w.skip_to("**");  // **scale, ...
  }
}

NeperTess parse(Words& w) {
  NeperTess t;
  bool periodic = false;
  t.dimensions = read_header(w, periodic);
  w.expect("**cell", "after **general");
  read_cells(w, t);
  for (std::string field = w.next(); field != "***end"; field = w.next()) {
    if (field.empty()) w.fail("ends before ***end");
    if (field.rfind("**", 0) != 0) w.fail("expected a field (**NAME), found '" + field + "'");
    read_field(w, t, field);
  }
  if (t.vertices.empty() || t.faces.empty()) w.fail("has no **vertex or no **face");
  if (t.domain_type.empty()) w.fail("has no **domain");
  if (periodic != t.periodic)
    w.fail(periodic ? "is of type periodic but has no **periodicity" : "has a **periodicity but is of type standard");
  const std::size_t cells = t.dimensions == 2 ? t.faces.size() : t.polyhedra.size();
  if (cells != t.seeds.size())
    w.fail(std::to_string(t.seeds.size()) + " cells but " + std::to_string(cells) +
           (t.dimensions == 2 ? " faces" : " polyhedra"));
  return t;
}

}  // namespace

NeperTess read_neper_tess(const std::filesystem::path& file) {
  Words w(read_text_file(file, "Neper tessellation"), file);
  return parse(w);
}

}  // namespace grainmesh
