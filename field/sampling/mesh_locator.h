#pragma once
// Where a point lies in a VTK data set: the containing cell and its
// interpolation weights, through a static cell locator built once and
// shared by every array of the data set (mesh_field.h). Internal to
// field/: the renderer never sees it.

#include <cstdint>
#include <memory>
#include <vector>

#include "base/box3.h"

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

}  // namespace hsb
