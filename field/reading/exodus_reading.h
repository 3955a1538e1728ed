#pragma once
// Exodus II results (Sierra, MOOSE, Cubit, SEACAS, VTK's own writer),
// through VTK's vtkExodusIIReader: every element block, every nodal and
// element variable, at one time step, on the undeformed mesh (a stress
// belongs to the configuration it was computed on, and the picture of
// each step keeps one frame).
//
// VTK's reader "gloms" variables by their names into arrays, and gets
// tensors wrong: stressXX, stressXY, stressXZ, stressYY, stressYZ, stressZZ
// become a vector "stressX" and three scalars. So the glomming is undone
// here, each array split back into the variables the file names, and
// field/reading/component_arrays.h joins them by a rule that knows tensors.
// Internal to field/; the file is parsed only in a child process
// (field/reading/dataset_reading.h).

#include <string>
#include <vector>

#include <vtkDataObject.h>
#include <vtkSmartPointer.h>

namespace hsb {

// The blocks of the Exodus file `path` at time step `step` (−1: the
// first), each variable its own one-component array. Throws DataError for
// a file the reader refuses or a step beyond the file's.
vtkSmartPointer<vtkDataObject> read_exodus(const std::string& path, int step);

// The times of the file's steps, in order (none: a file without results).
std::vector<double> exodus_times(const std::string& path);

}  // namespace hsb
