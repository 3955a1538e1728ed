#pragma once
// A tensor field on any VTK data set (unstructured, structured, image data),
// sampled through a static cell locator built once and the containing cell's
// own interpolation functions. Internal to field/: the renderer never sees it.

#include <memory>
#include <vector>

#include "field/tensor_field.h"

class vtkDataSet;

namespace hsb {

enum class TensorLocation { points, cells };

class MeshField final : public TensorField {
 public:
  // `tensors` holds one tensor per point or per cell of `data`, which the
  // field keeps a reference to.
  MeshField(vtkDataSet* data, std::vector<Sym3> tensors, TensorLocation location);
  ~MeshField() override;

  Box3 bounds() const override { return bounds_; }
  // Point data: Σ w_i T_i with the cell's interpolation weights w_i (exact
  // for fields the cell type reproduces, e.g. linear fields on linear
  // cells). Cell data: the containing cell's tensor. Outside every cell —
  // also inside holes of a hollow body — nothing.
  std::optional<Sym3> sample(const Vec3& x) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Box3 bounds_;
};

}  // namespace hsb
