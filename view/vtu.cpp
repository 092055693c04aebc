#include "view/vtu.hpp"

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>

#include "common/errors.hpp"

namespace grainmesh {
namespace {

// Keeps VTK's errors (and warnings) from being printed as multi-line dumps: the first
// message is kept, for a one-line IoError, and the rest is dropped.
class ErrorCatcher final : public vtkCommand {
 public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* data) override {
    if (message.empty() && data != nullptr) {
      message = static_cast<const char*>(data);
      message = message.substr(0, message.find('\n'));
    }
  }
  void watch(vtkAlgorithm* algorithm) {
    for (vtkObject* o : {static_cast<vtkObject*>(algorithm), static_cast<vtkObject*>(algorithm->GetExecutive())}) {
      o->AddObserver(vtkCommand::ErrorEvent, this);
      o->AddObserver(vtkCommand::WarningEvent, this);
    }
  }
  std::string message;
};

// Writes `data` with VTK's XML writer W as raw appended binary (smaller and faster than
// base64), compressed with zlib: what every reader takes (meshio 5.0 knows no LZ4).
// Throws IoError naming the file and `kind` (VTU, VTP).
constexpr int kZlibLevel = 1;  // zlib's fastest (docs/python.md, *Files other tools read*)
template <typename W, typename D>
void write_xml(const std::filesystem::path& file, D* data, const char* kind) {
  vtkNew<W> writer;
  vtkNew<ErrorCatcher> errors;
  errors->watch(writer);
  writer->SetFileName(file.c_str());
  writer->SetInputData(data);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetCompressionLevel(kZlibLevel);
  if (writer->Write() != 1 || writer->GetErrorCode() != 0 || !errors->message.empty())
    throw IoError(file.string() + ": cannot write " + kind + " file" + (errors->message.empty() ? "" : ": " + errors->message));
}

// Adds `values` (one per cell of `cells`) to the grid as cell array `name`. Throws IoError
// when there are not that many.
template <typename Array, typename T>
void add_cell_array(vtkUnstructuredGrid* grid, const std::filesystem::path& file, const std::string& name,
                    const std::vector<T>& values, std::size_t cells) {
  if (values.size() != cells) throw IoError(file.string() + ": cell array " + name + " is not one value per cell");
  vtkNew<Array> a;
  a->SetName(name.c_str());
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k) a->SetValue(static_cast<vtkIdType>(k), values[k]);
  grid->GetCellData()->AddArray(a);
}

// Each list of labels as a field-data array of bytes (UInt8): the labels in UTF-8, each
// ended by a NUL. A string array would be VTK's own form, but meshio (5.0) refuses the
// file at it; bytes every reader takes (docs/python.md says how to decode them).
void add_labels(vtkDataObject* data, const std::vector<FieldLabels>& labels) {
  for (const FieldLabels& l : labels) {
    vtkNew<vtkUnsignedCharArray> bytes;
    bytes->SetName(l.name.c_str());
    for (const std::string& label : l.labels) {
      for (const char c : label) bytes->InsertNextValue(static_cast<unsigned char>(c));
      bytes->InsertNextValue(0);
    }
    data->GetFieldData()->AddArray(bytes);
  }
}

// The cell fields (`cells` cells) and labels of write_vtu into the grid. Throws IoError
// naming a field that has not one value (of its components) per cell.
void add_fields(vtkUnstructuredGrid* grid, const std::filesystem::path& file, std::size_t cells,
                const std::vector<CellField>& fields, const std::vector<FieldLabels>& labels) {
  for (const CellField& f : fields) {
    std::visit(
        [&](const auto& values) {
          using T = typename std::decay_t<decltype(values)>::value_type;
          const std::size_t per_cell = static_cast<std::size_t>(std::max(f.components, 1));
          if (values.size() != per_cell * cells)
            throw IoError(file.string() + ": cell field '" + f.name + "' has " + std::to_string(values.size()) +
                          " values for " + std::to_string(cells) + " cells" +
                          (per_cell > 1 ? " of " + std::to_string(per_cell) + " components" : ""));
          vtkSmartPointer<vtkDataArray> array;
          if constexpr (std::is_same_v<T, int>) array = vtkSmartPointer<vtkIntArray>::New();
          else array = vtkSmartPointer<vtkDoubleArray>::New();
          array->SetName(f.name.c_str());
          array->SetNumberOfComponents(static_cast<int>(per_cell));
          array->SetNumberOfTuples(static_cast<vtkIdType>(cells));
          for (std::size_t i = 0; i < values.size(); ++i)
            array->SetComponent(static_cast<vtkIdType>(i / per_cell), static_cast<int>(i % per_cell),
                                static_cast<double>(values[i]));
          grid->GetCellData()->AddArray(array);
        },
        f.values);
  }
  add_labels(grid, labels);
}

// write_vtu, for triangles and for cells.
template <typename Mesh>
void write_grid(const std::filesystem::path& file, const Mesh& mesh, const std::vector<CellField>& fields,
                const std::vector<FieldLabels>& labels) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.points.size()));
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.points[i].x, mesh.points[i].y, 0.0);

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const std::size_t cells = cell_count(mesh);
  grid->Allocate(static_cast<vtkIdType>(cells));
  std::vector<vtkIdType> ids;
  for (std::size_t c = 0; c < cells; ++c) {
    const std::span<const int> ring = cell_ring(mesh, c);
    ids.assign(ring.begin(), ring.end());
    grid->InsertNextCell(ring.size() == 3 ? VTK_TRIANGLE : VTK_POLYGON, static_cast<vtkIdType>(ids.size()), ids.data());
  }
  add_fields(grid, file, cells, fields, labels);
  write_xml<vtkXMLUnstructuredGridWriter>(file, grid.Get(), "VTU");
}

}  // namespace

void write_vtu(const std::filesystem::path& file, const TriMesh& mesh, const std::vector<CellField>& fields,
               const std::vector<FieldLabels>& labels) {
  write_grid(file, mesh, fields, labels);
}

void write_vtu(const std::filesystem::path& file, const CellMesh& mesh, const std::vector<CellField>& fields,
               const std::vector<FieldLabels>& labels) {
  write_grid(file, mesh, fields, labels);
}

void write_tessellation_vtp(const std::filesystem::path& file, const Tessellation& t) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(t.vertices.size()));
  for (std::size_t i = 0; i < t.vertices.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), t.vertices[i].x, t.vertices[i].y, 0.0);
  vtkNew<vtkCellArray> polys, lines;
  std::vector<std::array<int, 6>> data;  // kind, grain, phase, region, left, right
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    const Region& region = t.regions[r];
    if (region.rings.size() != 1) continue;
    std::vector<vtkIdType> ids(region.rings[0].begin(), region.rings[0].end());
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    data.push_back({0, region.grain, region.phase, static_cast<int>(r), -1, -1});
  }
  for (const TessEdge& e : t.edges) {
    const vtkIdType ids[2] = {e.v0, e.v1};
    lines->InsertNextCell(2, ids);
    const int g = e.left >= 0 ? t.regions[e.left].grain : -1;
    const int p = e.left >= 0 ? t.regions[e.left].phase : -1;
    data.push_back({1, g, p, -1, e.left, e.right});
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->SetLines(lines);
  // vtkPolyData numbers verts, lines, polys, strips in that order.
  std::vector<std::array<int, 6>> ordered(data.begin() + polys->GetNumberOfCells(), data.end());
  ordered.insert(ordered.end(), data.begin(), data.begin() + polys->GetNumberOfCells());
  const char* names[6] = {"kind", "grain", "phase", "region", "left", "right"};
  for (int k = 0; k < 6; ++k) {
    vtkNew<vtkIntArray> array;
    array->SetName(names[k]);
    array->SetNumberOfTuples(static_cast<vtkIdType>(ordered.size()));
    for (std::size_t c = 0; c < ordered.size(); ++c) array->SetValue(static_cast<vtkIdType>(c), ordered[c][k]);
    poly->GetCellData()->AddArray(array);
  }
  write_xml<vtkXMLPolyDataWriter>(file, poly.Get(), "VTP");
}

namespace {

// The grid's points, in double precision, in their order.
void set_points(vtkUnstructuredGrid* grid, const std::vector<Vec3>& p) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i) points->SetPoint(static_cast<vtkIdType>(i), p[i].x, p[i].y, p[i].z);
  grid->SetPoints(points);
}

}  // namespace

void write_tet_vtu(const std::filesystem::path& file, const TetMesh& mesh,
                   const std::vector<std::pair<std::string, const std::vector<int>*>>& ints,
                   const std::vector<std::pair<std::string, const std::vector<double>*>>& reals,
                   const std::vector<FieldLabels>& labels) {
  vtkNew<vtkUnstructuredGrid> grid;
  set_points(grid, mesh.points);
  grid->Allocate(static_cast<vtkIdType>(mesh.tets.size()));
  for (const auto& t : mesh.tets) {
    const vtkIdType ids[4] = {t[0], t[1], t[2], t[3]};
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  for (const auto& [name, values] : ints) add_cell_array<vtkIntArray>(grid, file, name, *values, mesh.tets.size());
  for (const auto& [name, values] : reals) add_cell_array<vtkDoubleArray>(grid, file, name, *values, mesh.tets.size());
  add_labels(grid, labels);
  write_xml<vtkXMLUnstructuredGridWriter>(file, grid.Get(), "VTU");
}

namespace {

using IdLists = std::vector<std::vector<vtkIdType>>;  // a list of point ids per cell

// Polyhedra in the order meshio (5.0) reads right: by their number of corners, stably.
// meshio makes a block of each number in the order they first come but hands out the cell
// arrays in ascending order of it, so any other order scrambles them; VTK and ParaView
// take any order.
std::vector<std::size_t> polyhedra_order(const IdLists& corners) {
  std::vector<std::size_t> order(corners.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return corners[a].size() < corners[b].size();
  });
  return order;
}

// Inserts polyhedron c (its sorted corners, its faces as [n, ids...]) for each c of `order`.
void insert_polyhedra(vtkUnstructuredGrid* grid, const std::vector<std::size_t>& order, const IdLists& corners,
                      const IdLists& faces, const std::vector<vtkIdType>& face_count) {
  grid->Allocate(static_cast<vtkIdType>(order.size()));
  for (const std::size_t c : order)
    grid->InsertNextCell(VTK_POLYHEDRON, static_cast<vtkIdType>(corners[c].size()), corners[c].data(), face_count[c],
                         faces[c].data());
}

// `fields` with their cells taken in `order`.
std::vector<CellField> reordered(const std::vector<CellField>& fields, const std::vector<std::size_t>& order) {
  std::vector<CellField> out;
  for (const CellField& f : fields) {
    CellField g{f.name, {}, f.components};
    std::visit(
        [&](const auto& values) {
          std::decay_t<decltype(values)> v;
          const std::size_t k = static_cast<std::size_t>(std::max(f.components, 1));
          if (values.size() != k * order.size()) {
            v = values;  // add_fields names the field that has not one value per cell
          } else {
            v.reserve(values.size());
            for (const std::size_t c : order) v.insert(v.end(), values.begin() + c * k, values.begin() + (c + 1) * k);
          }
          g.values = std::move(v);
        },
        f.values);
    out.push_back(std::move(g));
  }
  return out;
}

// The corners of each polyhedron given by its faces as [n, ids...]: each once, ascending.
IdLists corners_of(const IdLists& faces) {
  IdLists corners(faces.size());
  for (std::size_t c = 0; c < faces.size(); ++c) {
    for (std::size_t k = 0; k < faces[c].size(); k += static_cast<std::size_t>(faces[c][k]) + 1)
      corners[c].insert(corners[c].end(), faces[c].begin() + static_cast<std::ptrdiff_t>(k) + 1,
                        faces[c].begin() + static_cast<std::ptrdiff_t>(k) + 1 + faces[c][k]);
    std::sort(corners[c].begin(), corners[c].end());
    corners[c].erase(std::unique(corners[c].begin(), corners[c].end()), corners[c].end());
  }
  return corners;
}

}  // namespace

void write_vtu(const std::filesystem::path& file, const PolyMesh& mesh, const std::vector<CellField>& fields,
               const std::vector<FieldLabels>& labels) {
  vtkNew<vtkUnstructuredGrid> grid;
  set_points(grid, mesh.points3d);
  // Each cell's faces as [n, ids...], turned outward: an owner's as stored, a neighbour's reversed.
  IdLists stream(static_cast<std::size_t>(mesh.cells));
  std::vector<vtkIdType> count(static_cast<std::size_t>(mesh.cells), 0);
  for (int f = 0; f < mesh.faces(); ++f) {
    const auto begin = mesh.face_points.begin() + mesh.face_start[f], end = mesh.face_points.begin() + mesh.face_start[f + 1];
    for (const int side : {0, 1}) {
      if (side == 1 && f >= mesh.internal_faces()) break;
      const std::size_t c = static_cast<std::size_t>(side == 0 ? mesh.owner[f] : mesh.neighbour[f]);
      stream[c].push_back(static_cast<vtkIdType>(end - begin));
      if (side == 0) stream[c].insert(stream[c].end(), begin, end);
      else stream[c].insert(stream[c].end(), std::make_reverse_iterator(end), std::make_reverse_iterator(begin));
      ++count[c];
    }
  }
  // In meshio's order (polyhedra_order), each cell's index in `cell`: OpenFOAM's.
  const IdLists corners = corners_of(stream);
  const std::vector<std::size_t> order = polyhedra_order(corners);
  insert_polyhedra(grid, order, corners, stream, count);
  std::vector<int> index(order.begin(), order.end());
  add_cell_array<vtkIntArray>(grid, file, "cell", index, order.size());
  add_fields(grid, file, static_cast<std::size_t>(mesh.cells), reordered(fields, order), labels);
  write_xml<vtkXMLUnstructuredGridWriter>(file, grid.Get(), "VTU");
}

void write_tessellation_vtu(const std::filesystem::path& file, const Tessellation3& t) {
  vtkNew<vtkUnstructuredGrid> grid;
  set_points(grid, t.vertices);
  IdLists stream(t.regions.size());  // each region's faces as [n, ids...]
  std::vector<vtkIdType> count(t.regions.size());
  for (std::size_t r = 0; r < t.regions.size(); ++r) {
    for (int f : t.regions[r].faces) {
      const Face3& face = t.faces[f];
      stream[r].push_back(static_cast<vtkIdType>(face.ring.size()));
      const std::size_t at = stream[r].size();
      stream[r].insert(stream[r].end(), face.ring.begin(), face.ring.end());
      if (face.back != static_cast<int>(r))
        std::reverse(stream[r].begin() + static_cast<std::ptrdiff_t>(at), stream[r].end());
    }
    count[r] = static_cast<vtkIdType>(t.regions[r].faces.size());
  }
  // In meshio's order (polyhedra_order), each region's index in `region`.
  const IdLists corners = corners_of(stream);
  const std::vector<std::size_t> order = polyhedra_order(corners);
  insert_polyhedra(grid, order, corners, stream, count);
  std::vector<int> grain, phase, region;
  for (const std::size_t r : order) {
    grain.push_back(t.regions[r].grain);
    phase.push_back(t.regions[r].phase);
    region.push_back(static_cast<int>(r));
  }
  for (const auto& [name, values] : {std::pair{"grain", &grain}, {"phase", &phase}, {"region", &region}})
    add_cell_array<vtkIntArray>(grid, file, name, *values, t.regions.size());
  FieldLabels names{"phase_names", {}};
  for (const Phase& p : t.phases) names.labels.push_back(p.name);
  add_labels(grid, {names});
  write_xml<vtkXMLUnstructuredGridWriter>(file, grid.Get(), "VTU");
}

namespace {

// The volume of 3D cell c of `grid`: a tetrahedron's signed volume (VTK's orientation is
// tet_volume's), a polyhedron's (1/6) sum over its faces' fan triangles (mean, a, b) of
// mean . (a x b), with its faces as they turn.
double solid_volume(vtkUnstructuredGrid* grid, vtkIdType c) {
  auto point = [&](vtkIdType id) {
    double x[3];
    grid->GetPoint(id, x);
    return Vec3{x[0], x[1], x[2]};
  };
  if (grid->GetCellType(c) == VTK_TETRA) {
    vtkIdType n = 0;
    const vtkIdType* v = nullptr;
    grid->GetCellPoints(c, n, v);
    return tet_volume(point(v[0]), point(v[1]), point(v[2]), point(v[3]));
  }
  vtkNew<vtkIdList> stream;
  grid->GetFaceStream(c, stream);
  double volume = 0.0;
  vtkIdType k = 1;
  for (vtkIdType f = 0; f < stream->GetId(0); ++f) {
    const vtkIdType n = stream->GetId(k++);
    std::vector<Vec3> p;
    Vec3 mean{};
    for (vtkIdType i = 0; i < n; ++i) {
      p.push_back(point(stream->GetId(k++)));
      mean += p.back() / static_cast<double>(n);
    }
    for (std::size_t i = 0; i < p.size(); ++i) volume += dot(mean, cross(p[i], p[(i + 1) % p.size()])) / 6.0;
  }
  return volume;
}

}  // namespace

VtuContents read_vtu(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) throw IoError(file.string() + ": no such file");
  // VTK's XML parser logs its own complaints to stderr; ours is the one-line error below.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  vtkNew<ErrorCatcher> errors;
  errors->watch(reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || grid == nullptr || !errors->message.empty())
    throw IoError(file.string() + ": cannot read VTU file (not a VTK XML unstructured grid, or damaged)");

  VtuContents out;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double x[3];
    grid->GetPoint(i, x);
    out.mesh.points.push_back({x[0], x[1]});
  }
  std::vector<int> ring;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    if (grid->GetCellType(c) == VTK_POLYHEDRON || grid->GetCellType(c) == VTK_TETRA) {
      out.solid_volumes.push_back(solid_volume(grid, c));
      continue;
    }
    if (grid->GetCellType(c) != VTK_TRIANGLE && grid->GetCellType(c) != VTK_POLYGON)
      throw IoError(file.string() + ": cell " + std::to_string(c) + " is neither a triangle nor a polygon");
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    grid->GetCellPoints(c, n, ids);
    ring.clear();
    for (vtkIdType k = 0; k < n; ++k) {
      if (ids[k] < 0 || ids[k] >= grid->GetNumberOfPoints())
        throw IoError(file.string() + ": cell " + std::to_string(c) + " names a point that is not in the file");
      ring.push_back(static_cast<int>(ids[k]));
    }
    out.mesh.add_cell(ring);
  }
  vtkCellData* cd = grid->GetCellData();
  for (int a = 0; a < cd->GetNumberOfArrays(); ++a) {
    vtkDataArray* array = cd->GetArray(a);
    if (array == nullptr) continue;
    const int components = array->GetNumberOfComponents();
    CellField f{array->GetName() ? array->GetName() : "", std::vector<int>{}, components};
    const std::size_t n = static_cast<std::size_t>(array->GetNumberOfTuples()) * static_cast<std::size_t>(components);
    auto component = [&](std::size_t i) {
      return array->GetComponent(static_cast<vtkIdType>(i / components), static_cast<int>(i % components));
    };
    if (array->GetDataType() == VTK_INT) {
      std::vector<int> v(n);
      for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<int>(component(i));
      f.values = std::move(v);
    } else {
      std::vector<double> v(n);
      for (std::size_t i = 0; i < n; ++i) v[i] = component(i);
      f.values = std::move(v);
    }
    out.fields.push_back(std::move(f));
  }
  vtkFieldData* fd = grid->GetFieldData();
  for (int a = 0; fd != nullptr && a < fd->GetNumberOfArrays(); ++a) {
    vtkAbstractArray* array = fd->GetAbstractArray(a);
    FieldLabels l{array->GetName() ? array->GetName() : "", {}};
    if (auto* strings = vtkStringArray::SafeDownCast(array)) {  // files written before the bytes
      for (vtkIdType i = 0; i < strings->GetNumberOfValues(); ++i) l.labels.push_back(strings->GetValue(i));
    } else if (auto* bytes = vtkUnsignedCharArray::SafeDownCast(array)) {
      std::string label;
      for (vtkIdType i = 0; i < bytes->GetNumberOfValues(); ++i) {
        if (const unsigned char c = bytes->GetValue(i); c != 0) label += static_cast<char>(c);
        else l.labels.push_back(std::exchange(label, {}));
      }
      if (!label.empty()) throw IoError(file.string() + ": field data '" + l.name + "': labels not ended by NUL");
    } else {
      continue;
    }
    out.labels.push_back(std::move(l));
  }
  return out;
}

const std::vector<int>* VtuContents::ints(const std::string& name) const {
  for (const CellField& f : fields)
    if (f.name == name && f.components == 1 && std::holds_alternative<std::vector<int>>(f.values))
      return &std::get<std::vector<int>>(f.values);
  return nullptr;
}

}  // namespace grainmesh
