#include "field/mesh_field.h"

#include <tbb/enumerable_thread_specific.h>
#include <vtkDataSet.h>
#include <vtkGenericCell.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

namespace hsb {

// Per-thread scratch, because FindCell's thread-safe form needs a caller-
// owned cell and weight buffer (trajectories are traced in parallel).
struct CellScratch {
  vtkSmartPointer<vtkGenericCell> cell = vtkSmartPointer<vtkGenericCell>::New();
  std::vector<double> weights;
};

struct MeshField::Impl {
  vtkSmartPointer<vtkDataSet> data;
  vtkSmartPointer<vtkStaticCellLocator> locator;
  std::vector<Sym3> tensors;
  TensorLocation location;
  double tolerance2;
  std::size_t max_cell_size;
  tbb::enumerable_thread_specific<CellScratch> scratch;
};

MeshField::MeshField(vtkDataSet* data, std::vector<Sym3> tensors, TensorLocation location)
    : impl_(std::make_unique<Impl>()) {
  impl_->data = data;
  impl_->tensors = std::move(tensors);
  impl_->location = location;
  double b[6];
  data->GetBounds(b);
  bounds_ = Box3{Vec3(b[0], b[2], b[4]), Vec3(b[1], b[3], b[5])};
  // A point on a cell's face is inside it up to round-off, not more: a looser
  // tolerance would let trajectories cut across a hollow body's hole. (VTK
  // 9.1's static locator ignores it and uses each cell's own test, which is
  // as strict; it is kept for locators that use it.)
  const double tolerance = 1e-9 * bounds_.diagonal();
  impl_->tolerance2 = tolerance * tolerance;
  impl_->max_cell_size = std::size_t(data->GetMaxCellSize());
  impl_->locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  impl_->locator->SetDataSet(data);
  impl_->locator->BuildLocator();
  // Some data sets build their cell links lazily on first access; do it here,
  // on one thread, before sampling goes parallel.
  vtkNew<vtkGenericCell> warm_up;
  if (data->GetNumberOfCells() > 0) data->GetCell(0, warm_up);
}

MeshField::~MeshField() = default;

std::optional<Sym3> MeshField::sample(const Vec3& x) const {
  CellScratch& scratch = impl_->scratch.local();
  if (scratch.weights.size() < impl_->max_cell_size) scratch.weights.resize(impl_->max_cell_size);
  double p[3] = {x.x(), x.y(), x.z()};
  double pcoords[3];
  const vtkIdType cell_id =
      impl_->locator->FindCell(p, impl_->tolerance2, scratch.cell.Get(), pcoords, scratch.weights.data());
  if (cell_id < 0) return std::nullopt;
  if (impl_->location == TensorLocation::cells) return impl_->tensors[std::size_t(cell_id)];
  Sym3 sum;
  const int n = int(scratch.cell->GetNumberOfPoints());
  for (int i = 0; i < n; ++i)
    sum = sum + scratch.weights[std::size_t(i)] * impl_->tensors[std::size_t(scratch.cell->GetPointId(i))];
  return sum;
}

}  // namespace hsb
