#pragma once
// A uniform (image-data) grid of tensors (or of scalars: a mask) with
// trilinear interpolation. Node (i, j, k) stands at
// origin + D (i·sx, j·sy, k·sz): D is the grid's
// direction matrix (VTK's Direction; the identity for an axis-aligned
// grid), whose columns are the directions of its i, j and k axes.

#include <array>
#include <vector>

#include "base/shared_values.h"
#include "field/sampling/field.h"

namespace hsb {

// T is Sym3 or double (instantiated in uniform_grid.cpp).
template <class T>
class UniformGrid final : public Field<T> {
 public:
  // `values` holds dims[0]*dims[1]*dims[2] values, x varying fastest (VTK's
  // point order). Every dimension must be at least 2.
  // `direction` must be invertible.
  UniformGrid(const Vec3& origin, const Vec3& spacing, const std::array<int, 3>& dims, SharedValues<T> values,
              const Mat3& direction = Mat3::Identity());

  // Samples `field` at the nodes of a dims[0]×dims[1]×dims[2] grid spanning
  // its bounds, so the analytic fields can be studied through the grid path.
  static UniformGrid sampled_from(const Field<T>& field, const std::array<int, 3>& dims);

  // The box around the grid's eight corners.
  Box3 bounds() const override;
  // Trilinear interpolation, component by component.
  std::optional<T> sample(const Vec3& x) const override;

  const T& node(int i, int j, int k) const;
  const std::array<int, 3>& dims() const { return dims_; }
  // The values at the nodes, x varying fastest.
  const std::vector<T>& values() const { return values_.vector(); }

 private:
  Vec3 origin_, spacing_;
  Mat3 direction_, to_index_;  // D, and D⁻¹ scaled by 1/spacing: world offset → index
  bool aligned_;               // D = I: index from the offset alone
  std::array<int, 3> dims_;
  SharedValues<T> values_;
};

using UniformGridField = UniformGrid<Sym3>;

}  // namespace hsb
