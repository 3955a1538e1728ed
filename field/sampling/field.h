#pragma once
// A field that can be sampled anywhere in its domain: tensors (stress,
// strain, diffusion), vectors (a flow's velocity) or scalars (an array a
// data file carries for colouring). One interface for the three: analytic
// fields, uniform grids and meshes implement it, trajectory integration and
// source placement consume it.

#include <optional>

#include "base/box3.h"
#include "field/tensor/sym3.h"

namespace hsb {

// Sampling is not on any rendering hot path, so a virtual call is fine here.
template <class T>
class Field {
 public:
  virtual ~Field() = default;

  // The domain's axis-aligned bounds.
  virtual Box3 bounds() const = 0;

  // The value at `x`, or nothing where there is no data: outside the
  // domain, inside a hole, or where the file holds NaN. Never non-finite.
  virtual std::optional<T> sample(const Vec3& x) const = 0;
};

// The field of data without volume (a point cloud, lines, a curved
// shell): its values stand at its points with nothing to interpolate in
// between, so it is sampled nowhere, and its values are drawn where they
// stand (field/reading/vtk_data.h, DataSites).
template <class T>
class PointsOnlyField final : public Field<T> {
 public:
  explicit PointsOnlyField(const Box3& bounds) : bounds_(bounds) {}
  Box3 bounds() const override { return bounds_; }
  std::optional<T> sample(const Vec3&) const override { return std::nullopt; }

 private:
  Box3 bounds_;
};

using TensorField = Field<Sym3>;
using VectorField = Field<Vec3>;
using ScalarField = Field<double>;

}  // namespace hsb
