#pragma once
// A data file read into one VTK data set, by the reader its format's entry
// in the registry names (field/reading/data_formats.h, format_reader.h),
// and checked for what no reader checks but everything after relies on.
// Parallel pieces and blocks are merged into one unstructured grid with
// their shared points joined, or one block read alone; a time series is
// read at one of its steps. Internal to field/.

#include <string>

#include <vtkAlgorithm.h>
#include <vtkDataSet.h>
#include <vtkSmartPointer.h>

#include "field/reading/data_arrays.h"
#include "field/reading/format_reader.h"
#include "field/reading/vtk_session.h"

namespace hsb {

// The data set in `path`, at the request's time step and block; VTK's
// complaints end up in `vtk`. Throws DataError naming the file.
vtkSmartPointer<vtkDataSet> read_dataset(const std::string& path, const VtkSession& vtk,
                                         const ReadRequest& request = {});

// The data set `arrays` describe (data_arrays.h), checked and made whole
// as a file's is after its reader. Throws DataError naming arrays.name.
vtkSmartPointer<vtkDataSet> read_arrays(const DataArrays& arrays);

// Why the data set has no volume to sample in between its points (a point
// cloud, lines, a curved shell: its values stand at its points only); ""
// for one that has.
std::string no_volume_reason(vtkDataSet* data);

// Runs `algorithm` in a child process first: VTK's filters trust the cells
// they are given, so a degenerate mesh can make them read past their
// buffers or loop. A crash or a hang in the child is one DataError naming
// `path` and `what` ran on it. (Files VTK parses are parsed only in a
// child: read_dataset.)
void update_safely(vtkAlgorithm* algorithm, const std::string& path, const char* what);

}  // namespace hsb
