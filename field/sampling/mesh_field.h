#pragma once
// A field on any VTK data set (unstructured, structured, image data): one
// array of the data set, a value per point or per cell, interpolated through
// the data set's locator (mesh_locator.h) with the cell's own functions.
// Tensors, vectors and colour scalars all go through the same locator:
// design §4, "interpolate the components, never eigenvectors". Internal to
// field/: the renderer never sees it.

#include <cmath>
#include <memory>
#include <vector>

#include "base/shared_values.h"
#include "field/sampling/field.h"
#include "field/sampling/mesh_locator.h"

namespace hsb {

inline bool is_finite_value(double v) { return std::isfinite(v); }
inline bool is_finite_value(const Vec3& v) { return v.allFinite(); }
inline bool is_finite_value(const Sym3& v) { return v.is_finite(); }

// T is double, Vec3 or Sym3.
template <class T>
class MeshField final : public Field<T> {
 public:
  MeshField(std::shared_ptr<const MeshLocator> locator, SharedValues<T> values, ValueLocation location)
      : locator_(std::move(locator)), values_(std::move(values)), location_(location) {}

  Box3 bounds() const override { return locator_->bounds(); }

  // Point data: Σ w_i v_i with the cell's interpolation weights w_i (exact
  // for fields the cell type reproduces). Cell data: the containing cell's
  // value. Outside every cell nothing, nor where a value is NaN (no data:
  // a NaN among a cell's points makes the whole cell no data).
  std::optional<T> sample(const Vec3& x) const override {
    const CellWeights* w = locator_->locate(x);
    if (!w) return std::nullopt;
    T value;
    if (location_ == ValueLocation::cells) {
      value = values_[std::size_t(w->cell)];
    } else {
      value = 0.0 * values_[std::size_t(w->points[0])];
      for (std::size_t i = 0; i < w->points.size(); ++i)
        value = value + w->weights[i] * values_[std::size_t(w->points[i])];
    }
    if (!is_finite_value(value)) return std::nullopt;
    return value;
  }

  const std::vector<T>& values() const { return values_.vector(); }

 private:
  std::shared_ptr<const MeshLocator> locator_;
  SharedValues<T> values_;
  ValueLocation location_;
};

}  // namespace hsb
