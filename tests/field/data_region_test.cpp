// The outline of the part of a grid that holds data (data_region.h): a
// ball of tensors in a background of zeros is outlined by a sphere, not
// the grid's box; a grid full of data, or with a few zero points, keeps
// its box; data reaching the grid's edge is closed there; an oblique
// grid's outline stands where its points do.

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPolyData.h>

#include <cmath>
#include <map>
#include <utility>

#include "base/point_extremes.h"
#include "field/reading/data_region.h"
#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"
#include "tests/vtk_written.h"

namespace hsb {
namespace {

const Box3 cube{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
constexpr double kRadius = 0.6, kSpacing = 2.0 / 32;

std::optional<Sym3> ball(const Vec3& p) {
  return p.norm() < kRadius ? Sym3{1, 2, 3, 0, 0, 0} : Sym3{0, 0, 0, 0, 0, 0};
}

TriangleMesh boundary_of(const std::string& file, const std::function<std::optional<Sym3>(const Vec3&)>& tensor) {
  return load_vtk_data({grid_written(test_temp_dir("data_region") / file, cube, {33, 33, 33}, tensor)}).boundary;
}

TEST(DataRegion, ABallInZerosIsOutlinedByItsSphere) {
  const TriangleMesh outline = boundary_of("ball.vti", ball);
  ASSERT_FALSE(outline.triangles.empty());
  ASSERT_EQ(outline.normals.size(), outline.vertices.size());
  // Within a voxel and a half of the sphere (the blur rounds the voxels'
  // staircase), nowhere near the grid's faces.
  for (const Vec3& v : outline.vertices) EXPECT_NEAR(v.norm(), kRadius, 1.5 * kSpacing) << v.transpose();
  const Box3 box = bounding_box(outline.vertices);
  EXPECT_LT(box.hi.maxCoeff(), kRadius + 1.5 * kSpacing);
  EXPECT_GT(box.hi.minCoeff(), kRadius - 1.5 * kSpacing);
}

TEST(DataRegion, AGridFullOfDataOrWithAFewZerosKeepsItsBox) {
  const auto full = [](const Vec3&) { return std::optional<Sym3>(Sym3{1, 2, 3, 0, 0, 0}); };
  // A slab of zeros one point thick: 1/33 of the points, below the share
  // that makes a background.
  const auto few = [](const Vec3& p) {
    return std::optional<Sym3>(std::fabs(p.x()) < 0.5 * kSpacing ? Sym3{} : Sym3{1, 2, 3, 0, 0, 0});
  };
  for (const auto& [file, tensor] : {std::pair{"full.vti", std::function<std::optional<Sym3>(const Vec3&)>(full)},
                                     std::pair{"few_zeros.vti", std::function<std::optional<Sym3>(const Vec3&)>(few)}}) {
    const Box3 box = bounding_box(boundary_of(file, tensor).vertices);
    EXPECT_NEAR((box.lo - cube.lo).norm(), 0.0, 1e-9) << file;
    EXPECT_NEAR((box.hi - cube.hi).norm(), 0.0, 1e-9) << file;
  }
}

TEST(DataRegion, DataReachingTheGridsEdgeIsClosedThere) {
  // Data in x < 0.3 only: the outline is a closed box-like surface, every
  // edge of it shared by exactly two triangles.
  const TriangleMesh outline = boundary_of("half.vti", [](const Vec3& p) {
    return std::optional<Sym3>(p.x() < 0.3 ? Sym3{1, 2, 3, 0, 0, 0} : Sym3{});
  });
  ASSERT_FALSE(outline.triangles.empty());
  // Normals split at sharp edges duplicate vertices: edges are counted
  // between positions, not indices.
  std::map<std::array<double, 3>, int> id;
  const auto key = [&](std::uint32_t v) {
    const Vec3& p = outline.vertices[v];
    return id.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, int(id.size())).first->second;
  };
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : outline.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = key(t[std::size_t(k)]), b = key(t[std::size_t((k + 1) % 3)]);
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  for (const auto& [edge, count] : edges) EXPECT_EQ(count, 2);
  const Box3 box = bounding_box(outline.vertices);
  EXPECT_LT(box.hi.x(), 0.3 + 1.5 * kSpacing);
  EXPECT_LT(box.lo.x(), -1.0 + 1e-9 + kSpacing);  // out to the grid's edge, closed just beyond it
}

TEST(DataRegion, AnObliqueGridsOutlineStandsWhereItsPointsDo) {
  // A ball about the physical point (2, 1, 0) of a grid turned 30° about z.
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(33, 33, 33);
  image->SetSpacing(kSpacing, kSpacing, kSpacing);
  image->SetOrigin(1, 0, -1);
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const double turn[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
  image->SetDirectionMatrix(turn);
  const Vec3 centre = Vec3(1, 0, -1) + Vec3(c - s, s + c, 1.0);  // index (16, 16, 16)
  std::vector<std::uint8_t> has_data(std::size_t(image->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i) {
    double p[3];
    image->GetPoint(i, p);
    has_data[std::size_t(i)] = (Vec3(p[0], p[1], p[2]) - centre).norm() < kRadius;
  }
  const vtkSmartPointer<vtkPolyData> surface = data_region_surface(image, has_data);
  ASSERT_TRUE(surface);
  ASSERT_GT(surface->GetNumberOfPoints(), 100);
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i) {
    double p[3];
    surface->GetPoint(i, p);
    EXPECT_NEAR((Vec3(p[0], p[1], p[2]) - centre).norm(), kRadius, 1.5 * kSpacing);
  }
  // Nothing to outline: no data, or no background.
  EXPECT_FALSE(data_region_surface(image, std::vector<std::uint8_t>(has_data.size(), 0)));
  EXPECT_FALSE(data_region_surface(image, std::vector<std::uint8_t>(has_data.size(), 1)));
}

}  // namespace
}  // namespace hsb
