#pragma once
// A uniform (image-data) grid of tensors with trilinear interpolation. Node
// (i, j, k) stands at origin + D (i·sx, j·sy, k·sz): D is the grid's
// direction matrix (VTK's Direction; the identity for an axis-aligned
// grid), whose columns are the directions of its i, j and k axes.

#include <array>
#include <vector>

#include "field/sampling/field.h"

namespace hsb {

class UniformGridField final : public TensorField {
 public:
  // `values` holds dims[0]*dims[1]*dims[2] tensors, x varying fastest (VTK's
  // point order). Every dimension must be at least 2.
  // `direction` must be invertible.
  UniformGridField(const Vec3& origin, const Vec3& spacing, const std::array<int, 3>& dims,
                   std::vector<Sym3> values, const Mat3& direction = Mat3::Identity());

  // Samples `field` at the nodes of a dims[0]×dims[1]×dims[2] grid spanning
  // its bounds, so the analytic fields can be studied through the grid path.
  static UniformGridField sampled_from(const TensorField& field, const std::array<int, 3>& dims);

  // The box around the grid's eight corners.
  Box3 bounds() const override;
  // Component-wise trilinear interpolation of the six components.
  std::optional<Sym3> sample(const Vec3& x) const override;

  const Sym3& node(int i, int j, int k) const;
  const std::array<int, 3>& dims() const { return dims_; }

 private:
  Vec3 origin_, spacing_;
  Mat3 direction_, to_index_;  // D, and D⁻¹ scaled by 1/spacing: world offset → index
  bool aligned_;               // D = I: index from the offset alone
  std::array<int, 3> dims_;
  std::vector<Sym3> values_;
};

}  // namespace hsb
