#pragma once
// Data a program already holds, handed over as arrays instead of a file:
// the library's and the Python module's way in (a result of FEniCS or
// SfePy still in memory, a NumPy array). A mesh's points and cells and
// its named arrays on points or cells, in VTK's cell types and node
// orders, are made into the data set a file's reader makes, and go
// through the same checks and rules from there (dataset_reading.h:
// checked_arrays): an array's component order, a 2-D result, flat cells,
// the tensor's kind. Every size and index is checked before anything is
// built, with one error naming the arrays and what was expected.

#include <cstdint>
#include <string>
#include <vector>

// Declared only: the renderer includes this (a scene's data may be
// arrays) without VTK's headers.
class vtkDataSet;
template <class T>
class vtkSmartPointer;

namespace hsb {

struct DataArrays {
  // What messages call the data, as they name a file.
  std::string name = "data arrays";
  std::vector<double> points;  // x, y, z of each point
  // The cells as VTK holds them: cell i's points are
  // connectivity[offsets[i] .. offsets[i + 1]), its type cell_types[i]
  // (VTK's numbers: 10 a tetrahedron, 12 a hexahedron, 24 a quadratic
  // tetrahedron, ...). offsets has one more entry than there are cells.
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;
  std::vector<std::uint8_t> cell_types;
  struct Array {
    std::string name;
    int components = 1;  // 1, 3 (vectors), 6 (a symmetric tensor, data.components names the order) or 9
    bool on_points = true;
    std::vector<double> values;  // components per point (or cell), one point after another
  };
  std::vector<Array> arrays;  // a 6-component array's order: data.components, as for a file
};

// The unstructured grid `arrays` describe. Throws DataError naming
// arrays.name for anything inconsistent (a count that is not a multiple
// of 3 or of the components, an index out of range, a cell type hsb does
// not read or with the wrong number of points, a coordinate that is not
// finite, two arrays of one name).
vtkSmartPointer<vtkDataSet> grid_of_arrays(const DataArrays& arrays);

// The SHA-1 of everything `arrays` hold (but their name), as a data
// file's bytes are hashed for an image's hsb:data_sha1 and --skip-existing.
std::string arrays_sha1(const DataArrays& arrays);

}  // namespace hsb
