#include "field/sampling/mesh_locator.h"

#include <tbb/enumerable_thread_specific.h>
#include <vtkDataSet.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

namespace hsb {

// Per-thread scratch, because FindCell's thread-safe form needs a caller-
// owned cell and weight buffer (trajectories are traced in parallel).
struct CellScratch {
  vtkSmartPointer<vtkGenericCell> cell = vtkSmartPointer<vtkGenericCell>::New();
  std::vector<double> vtk_weights;
  CellWeights result;
};

struct MeshLocator::Impl {
  vtkSmartPointer<vtkDataSet> data;
  vtkSmartPointer<vtkStaticCellLocator> locator;
  double tolerance2;
  std::size_t max_cell_size;
  tbb::enumerable_thread_specific<CellScratch> scratch;
};

MeshLocator::MeshLocator(vtkDataSet* data) : impl_(std::make_unique<Impl>()) {
  impl_->data = data;
  double b[6];
  data->GetBounds(b);
  bounds_ = Box3{Vec3(b[0], b[2], b[4]), Vec3(b[1], b[3], b[5])};
  // A point on a cell's face is inside it up to round-off, not more: a looser
  // tolerance would let trajectories cut across a hollow body's hole. (VTK
  // 9.1's static locator ignores FindCell's tolerance argument and uses
  // each cell's own test, which is as strict.)
  const double tolerance = 1e-9 * bounds_.diagonal();
  impl_->tolerance2 = tolerance * tolerance;
  impl_->max_cell_size = std::size_t(data->GetMaxCellSize());
  impl_->locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  impl_->locator->SetDataSet(data);
  // The locator's own tolerance pads every cell's bounds before the cell's
  // test; its default is an absolute 0.001, which for a part measured in
  // metres (a 1 mm part) covers the whole mesh, so every query tested every
  // cell: 160 µs a query instead of 1 µs. Relative to the data's size, it
  // costs the same in any unit.
  impl_->locator->SetTolerance(tolerance);
  impl_->locator->BuildLocator();
  // Some data sets build their cell links lazily on first access; do it here,
  // on one thread, before sampling goes parallel.
  vtkNew<vtkGenericCell> warm_up;
  if (data->GetNumberOfCells() > 0) data->GetCell(0, warm_up);
}

MeshLocator::~MeshLocator() = default;

const CellWeights* MeshLocator::locate(const Vec3& x) const {
  CellScratch& s = impl_->scratch.local();
  if (s.vtk_weights.size() < impl_->max_cell_size) s.vtk_weights.resize(impl_->max_cell_size);
  double p[3] = {x.x(), x.y(), x.z()};
  double pcoords[3];
  const vtkIdType cell = impl_->locator->FindCell(p, impl_->tolerance2, s.cell.Get(), pcoords, s.vtk_weights.data());
  if (cell < 0) return nullptr;
  CellWeights& w = s.result;
  w.cell = cell;
  const std::size_t n = std::size_t(s.cell->GetNumberOfPoints());
  w.points.resize(n);
  w.weights.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    w.points[i] = s.cell->GetPointId(int(i));
    w.weights[i] = s.vtk_weights[i];
  }
  return &w;
}

}  // namespace hsb
