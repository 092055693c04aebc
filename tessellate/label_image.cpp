#include "tessellate/label_image.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkTIFFReader.h>
#include <vtkTIFFWriter.h>
#include <vtkUnsignedShortArray.h>

#include "common/errors.hpp"
#include "common/ring.hpp"

namespace grainmesh {

namespace {

// VTK's own messages off while a file is read or written: our errors say what failed.
struct QuietVtk {
  bool was = vtkObject::GetGlobalWarningDisplay();
  QuietVtk() { vtkObject::GlobalWarningDisplayOff(); }
  ~QuietVtk() { vtkObject::SetGlobalWarningDisplay(was ? 1 : 0); }
  QuietVtk(const QuietVtk&) = delete;
  QuietVtk& operator=(const QuietVtk&) = delete;
};

std::string lower_extension(const std::filesystem::path& file) {
  std::string e = file.extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

}  // namespace

LabelImage read_label_image(const std::filesystem::path& file) {
  const std::string name = file.string();
  if (!std::ifstream(file, std::ios::binary)) throw IoError(name + ": cannot be read");
  const QuietVtk quiet;
  vtkNew<vtkPNGReader> png;
  vtkNew<vtkTIFFReader> tiff;
  vtkImageReader2* reader = nullptr;
  if (png->CanReadFile(name.c_str()) > 0)
    reader = png;
  else if (lower_extension(file).starts_with(".tif") && tiff->CanReadFile(name.c_str()) > 0)
    reader = tiff;
  if (reader == nullptr) throw GeometryError(name + ": not a PNG or TIFF image");
  reader->SetFileName(name.c_str());
  reader->Update();
  vtkImageData* data = reader->GetOutput();
  int dims[3] = {0, 0, 0};
  data->GetDimensions(dims);
  if (reader->GetErrorCode() != 0 || dims[0] < 1 || dims[1] < 1 || data->GetPointData()->GetScalars() == nullptr)
    throw GeometryError(name + ": the image could not be decoded (a damaged file?)");
  if (dims[2] != 1) throw GeometryError(name + ": an image of " + std::to_string(dims[2]) + " slices; one is read");
  const int type = data->GetScalarType();
  if (type != VTK_UNSIGNED_CHAR && type != VTK_UNSIGNED_SHORT)
    throw GeometryError(name + ": pixels of " + data->GetScalarTypeAsString() + "; 8- or 16-bit labels are read");
  const int components = data->GetNumberOfScalarComponents();
  if (components < 1 || components > 4)
    throw GeometryError(name + ": " + std::to_string(components) + " channels per pixel; grey or RGB(A) is read");
  LabelImage image;
  image.width = dims[0];
  image.height = dims[1];
  image.colour = components >= 3;
  image.labels.resize(static_cast<std::size_t>(dims[0]) * dims[1]);
  vtkDataArray* scalars = data->GetPointData()->GetScalars();
  const bool wide = type == VTK_UNSIGNED_SHORT;
  for (std::size_t p = 0; p < image.labels.size(); ++p) {
    auto channel = [&](int c) {
      return static_cast<std::uint32_t>(scalars->GetComponent(static_cast<vtkIdType>(p), c));
    };
    if (!image.colour) {
      image.labels[p] = channel(0);
    } else {
      // A colour of 16-bit channels keeps each channel's high byte.
      const int shift = wide ? 8 : 0;
      image.labels[p] = ((channel(0) >> shift) << 16) | ((channel(1) >> shift) << 8) | (channel(2) >> shift);
    }
  }
  // VTK's TIFF reader keeps the file's row order (the top row first); rows run upwards here.
  if (reader == tiff.GetPointer())
    for (int j = 0; j < image.height / 2; ++j)
      std::swap_ranges(image.labels.begin() + static_cast<std::ptrdiff_t>(j) * image.width,
                       image.labels.begin() + static_cast<std::ptrdiff_t>(j + 1) * image.width,
                       image.labels.begin() + static_cast<std::ptrdiff_t>(image.height - 1 - j) * image.width);
  return image;
}

void write_label_image(const std::filesystem::path& file, const LabelImage& image) {
  const std::string name = file.string();
  vtkNew<vtkImageData> data;
  data->SetDimensions(image.width, image.height, 1);
  vtkNew<vtkUnsignedShortArray> values;
  values->SetNumberOfTuples(static_cast<vtkIdType>(image.labels.size()));
  for (std::size_t p = 0; p < image.labels.size(); ++p) {
    if (image.labels[p] > 65535)
      throw GeometryError(name + ": label " + std::to_string(image.labels[p]) + " over 16 bits");
    values->SetValue(static_cast<vtkIdType>(p), static_cast<unsigned short>(image.labels[p]));
  }
  data->GetPointData()->SetScalars(values);
  const std::string ext = lower_extension(file);
  const QuietVtk quiet;
  int error = 0;
  if (ext == ".png") {
    vtkNew<vtkPNGWriter> w;
    w->SetFileName(name.c_str());
    w->SetInputData(data);
    w->Write();
    error = static_cast<int>(w->GetErrorCode());
  } else if (ext == ".tif" || ext == ".tiff") {
    vtkNew<vtkTIFFWriter> w;
    w->SetCompressionToNoCompression();
    w->SetFileName(name.c_str());
    w->SetInputData(data);
    w->Write();
    error = static_cast<int>(w->GetErrorCode());
  } else {
    throw GeometryError(name + ": writes .png or .tif images");
  }
  if (error != 0) throw IoError(name + ": cannot be written");
}

LabelImage draw_label_image(const Tessellation& t, int width) {
  LabelImage image;
  const double h = t.width / width;
  image.width = width;
  image.height = std::max(1, static_cast<int>(std::lround(t.height / h)));
  image.labels.assign(static_cast<std::size_t>(image.width) * image.height, 0);
  for (const Region& r : t.regions) {
    std::vector<std::vector<Vec2>> rings;
    for (const auto& ring : r.rings) rings.push_back(ring_points(t.vertices, ring));
    Vec2 lo = rings[0][0], hi = rings[0][0];
    for (const Vec2& p : rings[0])
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    const int i0 = std::max(0, static_cast<int>(std::floor(lo.x / h - 0.5))),
              i1 = std::min(image.width - 1, static_cast<int>(hi.x / h));
    const int j0 = std::max(0, static_cast<int>(std::floor(lo.y / h - 0.5))),
              j1 = std::min(image.height - 1, static_cast<int>(hi.y / h));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const Vec2 centre{(i + 0.5) * h, (j + 0.5) * h};
        bool inside = inside_ring(rings[0], centre);
        for (std::size_t q = 1; inside && q < rings.size(); ++q) inside = !inside_ring(rings[q], centre);
        if (inside)
          image.labels[static_cast<std::size_t>(j) * image.width + i] = static_cast<std::uint32_t>(r.grain + 1);
      }
  }
  return image;
}

}  // namespace grainmesh
