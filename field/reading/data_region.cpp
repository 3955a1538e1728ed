#include "field/reading/data_region.h"

#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <array>

namespace hsb {
namespace {

// One pass of the kernel (1 2 1)/4 along `axis` of a volume of `dims`
// points in x-fastest order, zero beyond its ends.
void blur_along(std::vector<float>& v, const std::array<int, 3>& dims, int axis) {
  const std::size_t stride = axis == 0 ? 1 : axis == 1 ? std::size_t(dims[0]) : std::size_t(dims[0]) * dims[1];
  const int n = dims[std::size_t(axis)];
  std::vector<float> line(static_cast<std::size_t>(n));
  const std::size_t lines = v.size() / std::size_t(n);
  for (std::size_t l = 0; l < lines; ++l) {
    // The first point of line l: l runs over the other two axes.
    const std::size_t first = axis == 0 ? l * std::size_t(n)
                              : axis == 1 ? (l / dims[0]) * stride * n + l % dims[0]
                                          : l;
    for (int i = 0; i < n; ++i) line[std::size_t(i)] = v[first + std::size_t(i) * stride];
    for (int i = 0; i < n; ++i) {
      const float before = i > 0 ? line[std::size_t(i - 1)] : 0.0f, after = i + 1 < n ? line[std::size_t(i + 1)] : 0.0f;
      v[first + std::size_t(i) * stride] = 0.25f * before + 0.5f * line[std::size_t(i)] + 0.25f * after;
    }
  }
}

}  // namespace

vtkSmartPointer<vtkPolyData> data_region_surface(vtkImageData* image, const std::vector<std::uint8_t>& has_data) {
  const vtkIdType points = image->GetNumberOfPoints();
  if (points < 8 || vtkIdType(has_data.size()) != points) return nullptr;
  const std::size_t with_data = std::size_t(std::count(has_data.begin(), has_data.end(), std::uint8_t(1)));
  if (with_data == 0 || double(has_data.size() - with_data) < kBackgroundShare * double(has_data.size())) return nullptr;

  // The flags in a grid padded by one empty point on every side.
  int extent[6];
  image->GetExtent(extent);
  const std::array<int, 3> inner{extent[1] - extent[0] + 1, extent[3] - extent[2] + 1, extent[5] - extent[4] + 1};
  const std::array<int, 3> dims{inner[0] + 2, inner[1] + 2, inner[2] + 2};
  std::vector<float> flags(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2], 0.0f);
  std::size_t p = 0;
  for (int k = 0; k < inner[2]; ++k)
    for (int j = 0; j < inner[1]; ++j)
      for (int i = 0; i < inner[0]; ++i, ++p)
        flags[(std::size_t(k + 1) * dims[1] + std::size_t(j + 1)) * dims[0] + std::size_t(i + 1)] = has_data[p];
  // Twice along each axis: a binomial kernel of five points, close to a
  // Gaussian of σ = 1 voxel.
  for (int pass = 0; pass < 2; ++pass)
    for (int axis = 0; axis < 3; ++axis) blur_along(flags, dims, axis);

  // Contoured in index space (the padded grid starts one point before the
  // image's extent), then placed where the image's points are.
  auto grid = vtkSmartPointer<vtkImageData>::New();
  grid->SetDimensions(dims[0], dims[1], dims[2]);
  grid->SetOrigin(extent[0] - 1, extent[2] - 1, extent[4] - 1);
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetName("has_data");
  values->SetNumberOfValues(vtkIdType(flags.size()));
  std::copy(flags.begin(), flags.end(), values->GetPointer(0));
  grid->GetPointData()->SetScalars(values);
  auto contour = vtkSmartPointer<vtkFlyingEdges3D>::New();
  contour->SetInputData(grid);
  contour->SetValue(0, 0.5);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  vtkSmartPointer<vtkPolyData> surface = contour->GetOutput();
  vtkPoints* vertices = surface->GetPoints();
  if (!vertices || surface->GetNumberOfPolys() == 0) return nullptr;
  for (vtkIdType v = 0; v < vertices->GetNumberOfPoints(); ++v) {
    double index[3], xyz[3];
    vertices->GetPoint(v, index);
    image->TransformContinuousIndexToPhysicalPoint(index, xyz);
    vertices->SetPoint(v, xyz);
  }
  return surface;
}

}  // namespace hsb
