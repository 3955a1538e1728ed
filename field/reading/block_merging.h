#pragma once
// Files of several parts, made one unstructured grid: a parallel file's
// pieces (.pvtu), a multiblock file's blocks (.vtm) and an Exodus file's
// element blocks, merged, or one block alone when the scene names it
// (data.block); then the points the parts share joined into one. The
// blocks a file had are recorded, for `hsb info`. Internal to field/.

#include <string>
#include <vector>

#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

namespace hsb {

// The data sets with cells in `read` (a composite data set, or one data
// set) appended into one grid, ghost cells left out; or, when `block` is
// not "", only the block of that name (else of that index, counting from
// 0 in the file's order). Arrays that not every part has are dropped.
// Records each block's name and cell count. Throws DataError naming
// `path` when no part has cells or no block is `block` (listing those
// there are).
vtkSmartPointer<vtkDataSet> merged(vtkDataObject* read, const std::string& path, const std::string& block);

// `grid` with the points at the same place joined into one, as pieces
// share them: otherwise each piece's faces at its neighbours read as the
// body's boundary, and a trajectory stops at them. The cells must name
// existing points.
vtkSmartPointer<vtkUnstructuredGrid> joined(vtkUnstructuredGrid* grid);

struct BlockOfFile {
  std::string name;
  long long cells = 0;
  bool read = true;  // merged into the data set (all of them, or the one data.block names)
};

// What merged() recorded of the file's blocks; none for a file of one part.
std::vector<BlockOfFile> recorded_blocks(vtkDataSet* data);

}  // namespace hsb
