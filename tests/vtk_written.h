#pragma once
// Test data written by VTK's own writers, with their defaults, as the
// tools users have write it.

#include <gtest/gtest.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLImageDataWriter.h>

#include <array>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "base/box3.h"
#include "base/vec3.h"
#include "field/tensor/sym3.h"

namespace hsb {

// `data` written to `path` by VTK's `Writer` (a failed write fails the
// test); returns `path`.
template <class Writer>
std::string written_by(vtkDataObject* data, const std::filesystem::path& path) {
  auto writer = vtkSmartPointer<Writer>::New();
  writer->SetInputData(data);
  writer->SetFileName(path.string().c_str());
  EXPECT_EQ(writer->Write(), 1) << path;
  return path.string();
}

// A 6-component array named `name` of `tensor` at each of `data`'s points,
// in VTK's symmetric order (XX YY ZZ XY YZ XZ); NaN where it gives none.
inline vtkSmartPointer<vtkDoubleArray> tensors_at_points(
    vtkDataSet* data, const std::string& name, const std::function<std::optional<Sym3>(const Vec3&)>& tensor) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name.c_str());
  a->SetNumberOfComponents(6);
  a->SetNumberOfTuples(data->GetNumberOfPoints());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    const std::optional<Sym3> s = tensor(Vec3(p[0], p[1], p[2]));
    const double v[6] = {s ? s->xx : nan, s ? s->yy : nan, s ? s->zz : nan,
                         s ? s->xy : nan, s ? s->yz : nan, s ? s->xz : nan};
    a->SetTuple(i, v);
  }
  return a;
}

// A scalar array named `name` of `value` at each of `data`'s points.
inline vtkSmartPointer<vtkDoubleArray> scalars_at_points(vtkDataSet* data, const std::string& name,
                                                         const std::function<double(const Vec3&)>& value) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name.c_str());
  a->SetNumberOfTuples(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    a->SetValue(i, value(Vec3(p[0], p[1], p[2])));
  }
  return a;
}

struct ScalarArray {
  std::string name;
  std::function<double(const Vec3&)> value;
};

// A grid of `n` points over `box` holding `tensor` as an array named
// `name` (NaN where it gives none: outside the body; none at all for an
// empty function), and each of `scalars`, written as a .vti the way VTK
// writes it; returns `path`.
inline std::string grid_written(const std::filesystem::path& path, const Box3& box, const std::array<int, 3>& n,
                                const std::function<std::optional<Sym3>(const Vec3&)>& tensor,
                                const std::string& name = "stress", const std::vector<ScalarArray>& scalars = {}) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n[0], n[1], n[2]);
  image->SetOrigin(box.lo.x(), box.lo.y(), box.lo.z());
  const Vec3 size = box.size();
  image->SetSpacing(size.x() / (n[0] - 1), size.y() / (n[1] - 1), size.z() / (n[2] - 1));
  if (tensor) image->GetPointData()->AddArray(tensors_at_points(image, name, tensor));
  for (const ScalarArray& s : scalars) image->GetPointData()->AddArray(scalars_at_points(image, s.name, s.value));
  return written_by<vtkXMLImageDataWriter>(image, path);
}

}  // namespace hsb
