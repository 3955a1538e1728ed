#pragma once
// A tensor field on any VTK data set (unstructured, structured, image data):
// the six components interpolated through the data set's locator
// (mesh_locator.h). Internal to field/: the renderer never sees it.

#include <memory>
#include <vector>

#include "field/mesh_locator.h"
#include "field/tensor_field.h"

namespace hsb {

class MeshField final : public TensorField {
 public:
  MeshField(std::shared_ptr<const MeshLocator> locator, std::vector<Sym3> tensors, ValueLocation location)
      : tensors_(std::move(locator), std::move(tensors), location) {}

  Box3 bounds() const override { return tensors_.bounds(); }
  // Point data: Σ w_i T_i with the cell's interpolation weights w_i. Cell
  // data: the containing cell's tensor. Outside every cell nothing, nor
  // where a tensor is NaN (no data).
  std::optional<Sym3> sample(const Vec3& x) const override {
    std::optional<Sym3> s = tensors_.sample(x);
    if (s && !s->is_finite()) return std::nullopt;
    return s;
  }

 private:
  MeshArray<Sym3> tensors_;
};

}  // namespace hsb
