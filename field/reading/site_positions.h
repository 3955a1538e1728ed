#pragma once
// Where a data set's values stand (vtk_data.h, DataSites): a list of
// points, or the nodes of an image volume's grid, each computed when it is
// asked for. A diffusion volume's nodes listed would take 24 bytes a
// voxel, 16 MB for 88³ and 400 MB for 256³, at the moment its tensors are
// read; the grid takes a few numbers.

#include <array>
#include <cstddef>
#include <vector>

#include "base/vec3.h"

namespace hsb {

class SitePositions {
 public:
  SitePositions() = default;
  // A list (implicit, so a vector goes where positions do).
  SitePositions(std::vector<Vec3> listed) : listed_(std::move(listed)) {}
  // The nodes of a dims[0] × dims[1] × dims[2] grid, x varying fastest
  // (VTK's point order): node (i, j, k) at
  // origin + D ((first[0] + i) s_x, (first[1] + j) s_y, (first[2] + k) s_z),
  // as vtkImageData places its points (`first`: its extent's start, D its
  // direction matrix, s its spacing).
  SitePositions(const Vec3& origin, const Vec3& spacing, const Mat3& direction, const std::array<int, 3>& first,
                const std::array<int, 3>& dims);

  std::size_t size() const { return grid_ ? count_ : listed_.size(); }
  bool empty() const { return size() == 0; }
  Vec3 operator[](std::size_t i) const;

 private:
  std::vector<Vec3> listed_;
  bool grid_ = false, aligned_ = true;
  Vec3 origin_ = Vec3::Zero(), spacing_ = Vec3::Ones();
  Mat3 direction_ = Mat3::Identity();
  std::array<double, 3> first_{};
  std::size_t nx_ = 0, ny_ = 0, count_ = 0;
};

}  // namespace hsb
