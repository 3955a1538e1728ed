#include "field/reading/data_arrays.h"

#include <vtkCellArray.h>
#include <vtkDataSet.h>
#include <vtkSmartPointer.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "base/sha1.h"
#include "field/reading/data_error.h"

namespace hsb {
namespace {

// The cell types a file's readers hand on, with their points: linear and
// quadratic cells of every dimension (a surface or a line of points is
// read, and said to have no volume, as from a file).
const std::map<int, int>& points_of_cell_types() {
  static const std::map<int, int> points = {
      {VTK_VERTEX, 1},          {VTK_LINE, 2},
      {VTK_TRIANGLE, 3},        {VTK_PIXEL, 4},
      {VTK_QUAD, 4},            {VTK_TETRA, 4},
      {VTK_VOXEL, 8},           {VTK_HEXAHEDRON, 8},
      {VTK_WEDGE, 6},           {VTK_PYRAMID, 5},
      {VTK_QUADRATIC_EDGE, 3},  {VTK_QUADRATIC_TRIANGLE, 6},
      {VTK_QUADRATIC_QUAD, 8},  {VTK_QUADRATIC_TETRA, 10},
      {VTK_QUADRATIC_HEXAHEDRON, 20}, {VTK_QUADRATIC_WEDGE, 15},
      {VTK_QUADRATIC_PYRAMID, 13}};
  return points;
}

[[noreturn]] void refuse(const DataArrays& arrays, const std::string& what) {
  throw DataError(arrays.name + ": " + what);
}

std::string count(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

vtkSmartPointer<vtkDataSet> grid_of_arrays(const DataArrays& arrays) {
  if (arrays.points.empty()) refuse(arrays, "no points");
  if (arrays.points.size() % 3 != 0)
    refuse(arrays, "points holds " + count(arrays.points.size(), "value", "values") +
                       ", not three (x, y, z) for each point");
  const std::size_t n_points = arrays.points.size() / 3;
  for (std::size_t i = 0; i < arrays.points.size(); ++i)
    if (!std::isfinite(arrays.points[i]))
      refuse(arrays, "point " + std::to_string(i / 3) + "'s " + "xyz"[i % 3] + " is " + std::to_string(arrays.points[i]) +
                         ", not a finite coordinate");
  const std::size_t n_cells = arrays.cell_types.size();
  if (arrays.offsets.size() != n_cells + 1)
    refuse(arrays, "offsets holds " + count(arrays.offsets.size(), "entry", "entries") + " for " +
                       count(n_cells, "cell type", "cell types") + "; it needs one more than there are cells");
  if (arrays.offsets.front() != 0) refuse(arrays, "offsets starts at " + std::to_string(arrays.offsets.front()) + ", not 0");
  if (std::uint64_t(arrays.offsets.back()) != arrays.connectivity.size())
    refuse(arrays, "offsets ends at " + std::to_string(arrays.offsets.back()) + " but connectivity holds " +
                       count(arrays.connectivity.size(), "index", "indices"));
  for (std::size_t c = 0; c < n_cells; ++c) {
    const auto known = points_of_cell_types().find(arrays.cell_types[c]);
    if (known == points_of_cell_types().end())
      refuse(arrays, "cell " + std::to_string(c) + " has VTK cell type " + std::to_string(int(arrays.cell_types[c])) +
                         ", which is not one hsb reads (linear and quadratic cells: 1, 3, 5, 8-14, 21-27)");
    const std::int64_t size = arrays.offsets[c + 1] - arrays.offsets[c];
    if (size != known->second)
      refuse(arrays, "cell " + std::to_string(c) + " (VTK type " + std::to_string(known->first) + ") has " +
                         std::to_string(size) + " points; its type has " + std::to_string(known->second));
  }
  for (std::size_t i = 0; i < arrays.connectivity.size(); ++i)
    if (arrays.connectivity[i] < 0 || std::uint64_t(arrays.connectivity[i]) >= n_points)
      refuse(arrays, "connectivity[" + std::to_string(i) + "] is " + std::to_string(arrays.connectivity[i]) +
                         ", not a point (there are " + count(n_points, "point", "points") + ")");
  std::set<std::pair<bool, std::string>> names;  // unique on the points, and on the cells, as in a file
  for (const DataArrays::Array& a : arrays.arrays) {
    if (a.name.empty()) refuse(arrays, "an array has no name; data.array names the one to draw");
    if (!names.insert({a.on_points, a.name}).second)
      refuse(arrays, std::string("two arrays on its ") + (a.on_points ? "points" : "cells") + " are named \"" + a.name +
                         "\"");
    if (a.components != 1 && a.components != 3 && a.components != 6 && a.components != 9)
      refuse(arrays, "array \"" + a.name + "\" has " + std::to_string(a.components) +
                         " components; hsb reads 1 (a scalar), 3 (vectors), 6 or 9 (tensors)");
    const std::size_t holders = a.on_points ? n_points : n_cells;
    if (a.values.size() != holders * std::size_t(a.components))
      refuse(arrays, "array \"" + a.name + "\" holds " + count(a.values.size(), "value", "values") + "; " +
                         std::to_string(a.components) + " for each of its " +
                         count(holders, a.on_points ? "point" : "cell", a.on_points ? "points" : "cells") + " are " +
                         std::to_string(holders * std::size_t(a.components)));
  }

  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vtkIdType(n_points));
  std::copy(arrays.points.begin(), arrays.points.end(),
            static_cast<vtkDoubleArray*>(points->GetData())->WritePointer(0, vtkIdType(arrays.points.size())));
  grid->SetPoints(points);
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(vtkIdType(arrays.offsets.size()));
  std::copy(arrays.offsets.begin(), arrays.offsets.end(), offsets->GetPointer(0));
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  connectivity->SetNumberOfValues(vtkIdType(arrays.connectivity.size()));
  std::copy(arrays.connectivity.begin(), arrays.connectivity.end(), connectivity->GetPointer(0));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  auto types = vtkSmartPointer<vtkUnsignedCharArray>::New();
  types->SetNumberOfValues(vtkIdType(n_cells));
  std::copy(arrays.cell_types.begin(), arrays.cell_types.end(), types->GetPointer(0));
  grid->SetCells(types, cells);
  for (const DataArrays::Array& a : arrays.arrays) {
    auto values = vtkSmartPointer<vtkDoubleArray>::New();
    values->SetName(a.name.c_str());
    values->SetNumberOfComponents(a.components);
    values->SetNumberOfTuples(vtkIdType(a.values.size() / std::size_t(a.components)));
    std::copy(a.values.begin(), a.values.end(), values->GetPointer(0));
    (a.on_points ? static_cast<vtkDataSetAttributes*>(grid->GetPointData())
                 : static_cast<vtkDataSetAttributes*>(grid->GetCellData()))
        ->AddArray(values);
  }
  return grid;
}

std::string arrays_sha1(const DataArrays& arrays) {
  Sha1 hash;
  const auto add = [&](const auto& values) {
    const std::uint64_t n = values.size();
    hash.append(&n, sizeof n);
    hash.append(values.data(), values.size() * sizeof(values[0]));
  };
  add(arrays.points);
  add(arrays.connectivity);
  add(arrays.offsets);
  add(arrays.cell_types);
  for (const DataArrays::Array& a : arrays.arrays) {
    add(a.name);
    const std::int32_t layout[2] = {a.components, a.on_points};
    hash.append(layout, sizeof layout);
    add(a.values);
  }
  return hash.hex();
}

}  // namespace hsb
