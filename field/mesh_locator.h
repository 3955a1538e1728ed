#pragma once
// Where a point lies in a VTK data set: the containing cell and its
// interpolation weights, through a static cell locator built once. Every
// array of the data set (tensors, vectors, colour scalars) is interpolated
// through the same locator: design §4, "interpolate the components, never
// eigenvectors". Internal to field/: the renderer never sees it.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "field/box3.h"

class vtkDataSet;

namespace hsb {

enum class ValueLocation { points, cells };

// The cell containing a point: for point data, the weights of its points.
struct CellWeights {
  std::int64_t cell = -1;
  std::vector<std::int64_t> points;
  std::vector<double> weights;
};

class MeshLocator {
 public:
  // Keeps a reference to `data`.
  explicit MeshLocator(vtkDataSet* data);
  ~MeshLocator();

  Box3 bounds() const { return bounds_; }
  // The cell containing `x` and its weights (this thread's scratch, valid
  // until its next call), or null outside every cell, also inside the hole
  // of a hollow body.
  const CellWeights* locate(const Vec3& x) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Box3 bounds_;
};

// One array of the data set, one value per point or cell, interpolated
// with the cell's own functions: Σ w_i v_i for point data (exact for fields
// the cell type reproduces), the containing cell's value for cell data.
// T is double, Vec3 or Sym3.
template <class T>
class MeshArray {
 public:
  MeshArray(std::shared_ptr<const MeshLocator> locator, std::vector<T> values, ValueLocation location)
      : locator_(std::move(locator)), values_(std::move(values)), location_(location) {}

  Box3 bounds() const { return locator_->bounds(); }
  std::optional<T> sample(const Vec3& x) const {
    const CellWeights* w = locator_->locate(x);
    if (!w) return std::nullopt;
    if (location_ == ValueLocation::cells) return values_[std::size_t(w->cell)];
    T sum = 0.0 * values_[std::size_t(w->points[0])];
    for (std::size_t i = 0; i < w->points.size(); ++i) sum = sum + w->weights[i] * values_[std::size_t(w->points[i])];
    return sum;
  }
  const std::vector<T>& values() const { return values_; }

 private:
  std::shared_ptr<const MeshLocator> locator_;
  std::vector<T> values_;
  ValueLocation location_;
};

}  // namespace hsb
