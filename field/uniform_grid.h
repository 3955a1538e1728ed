#pragma once
// A uniform (image-data) grid of tensors with trilinear interpolation.

#include <array>
#include <vector>

#include "field/tensor_field.h"

namespace hsb {

class UniformGridField final : public TensorField {
 public:
  // `values` holds dims[0]*dims[1]*dims[2] tensors, x varying fastest (VTK's
  // point order). Every dimension must be at least 2.
  UniformGridField(const Vec3& origin, const Vec3& spacing, const std::array<int, 3>& dims,
                   std::vector<Sym3> values);

  // Samples `field` at the nodes of a dims[0]×dims[1]×dims[2] grid spanning
  // its bounds, so the analytic fields can be studied through the grid path.
  static UniformGridField sampled_from(const TensorField& field, const std::array<int, 3>& dims);

  Box3 bounds() const override;
  // Component-wise trilinear interpolation of the six components.
  std::optional<Sym3> sample(const Vec3& x) const override;

  const Sym3& node(int i, int j, int k) const;
  const std::array<int, 3>& dims() const { return dims_; }

 private:
  Vec3 origin_, spacing_;
  std::array<int, 3> dims_;
  std::vector<Sym3> values_;
};

}  // namespace hsb
