#pragma once
// A symmetric tensor field that can be sampled anywhere in its domain.

#include <optional>

#include "field/box3.h"
#include "field/sym3.h"

namespace hsb {

// The interface every data set offers to trajectory integration and source
// placement: analytic fields, uniform grids and (later) unstructured meshes.
// Sampling is not on any rendering hot path, so a virtual call is fine here.
class TensorField {
 public:
  virtual ~TensorField() = default;

  // The domain's axis-aligned bounds.
  virtual Box3 bounds() const = 0;

  // The tensor at `x`, or nothing when `x` lies outside the domain.
  // Never returns a non-finite tensor.
  virtual std::optional<Sym3> sample(const Vec3& x) const = 0;
};

}  // namespace hsb
