#pragma once
// NRRD volumes (Teem's `tend`, 3D Slicer, ITK), read by hsb itself: VTK's
// vtkNrrdReader takes neither Teem's tensor kinds nor `space directions`.
// What is read:
//  - a header in the file (.nrrd) or apart from its data (.nhdr with
//    `data file:`); raw, ASCII or gzip-compressed data, either endianness,
//    any of NRRD's number types;
//  - three space axes placed by `space origin` and `space directions`
//    (or by `spacings`), so an oblique volume stays oblique;
//  - a first axis of kind 3D-masked-symmetric-matrix (Teem's seven values:
//    a confidence, then XX XY XZ YY YZ ZZ; a confidence below 0.5 is no
//    data), 3D-symmetric-matrix (six), 3D-matrix (nine, row by row),
//    3D-masked-matrix (ten) or 3-vector; without a kind, its count of
//    values says which;
//  - the `measurement frame`: tensors are turned from it into the space.
// The tensors come out in VTK's order, with the layout they were read
// from recorded (field/reading/component_arrays.h). Internal to field/; the file
// is parsed only in a child process (field/reading/dataset_reading.h).

#include <string>
#include <vector>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

namespace hsb {

// The volume in the NRRD file `path`. Throws DataError naming the file
// and the header line for anything it cannot read as described.
vtkSmartPointer<vtkImageData> read_nrrd(const std::string& path);

// The files reading `path` reads: itself, and a detached header's data file.
std::vector<std::string> nrrd_files(const std::string& path);

}  // namespace hsb
