#pragma once
// What a program holding a result in memory would hand over as data
// arrays (field/reading/data_arrays.h): an unstructured grid's points,
// cells and arrays, read here from a .vtu with VTK.

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <string>

#include "field/reading/data_arrays.h"

namespace hsb {

inline DataArrays data_arrays_of(const std::string& vtu, const std::string& name) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(vtu.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  DataArrays arrays;
  arrays.name = name;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double p[3];
    grid->GetPoint(i, p);
    arrays.points.insert(arrays.points.end(), p, p + 3);
  }
  vtkCellArray* cells = grid->GetCells();
  arrays.offsets.push_back(0);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    vtkIdType n;
    const vtkIdType* ids;
    cells->GetCellAtId(c, n, ids);
    arrays.connectivity.insert(arrays.connectivity.end(), ids, ids + n);
    arrays.offsets.push_back(std::int64_t(arrays.connectivity.size()));
    arrays.cell_types.push_back(std::uint8_t(grid->GetCellType(c)));
  }
  for (const bool on_points : {true, false}) {
    vtkDataSetAttributes* holder = on_points ? static_cast<vtkDataSetAttributes*>(grid->GetPointData())
                                             : static_cast<vtkDataSetAttributes*>(grid->GetCellData());
    for (int a = 0; a < holder->GetNumberOfArrays(); ++a) {
      vtkDataArray* array = holder->GetArray(a);
      DataArrays::Array given{array->GetName(), array->GetNumberOfComponents(), on_points, {}};
      for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
        for (int k = 0; k < given.components; ++k) given.values.push_back(array->GetComponent(t, k));
      arrays.arrays.push_back(std::move(given));
    }
  }
  return arrays;
}

}  // namespace hsb
