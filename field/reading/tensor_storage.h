#pragma once
// Six-component tensor arrays whose memory is already the field's own: a
// volume reader writes its tensors into a std::vector<Sym3> that a VTK
// double array only borrows, and read_tensors() takes the vector over
// instead of copying the array into a new one. For Teem's helix at 136³
// that leaves out a 60 MB float array written, read back and freed beside
// the 120 MB of doubles, and its first writes (on a virtual machine whose
// host reclaims idle memory, the slowest part of reading a volume). The
// NRRD and NIfTI readers both make their arrays here (volume_array).
// Internal to field/.

#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>

#include <vector>

#include "field/tensor/sym3.h"

namespace hsb {

// A double array of `count` tuples of six components in VTK's order
// (XX YY ZZ XY YZ XZ, Sym3's own layout), its values zero, on memory it
// carries as a vector of Sym3 (on huge pages, first written on every core).
vtkSmartPointer<vtkDoubleArray> tensor_array_on_storage(vtkIdType count);

// The vector under `array` when it is one made above, taken over and the
// array left empty (nothing reads freed memory through it); otherwise an
// empty vector and the array untouched. The values are the array's as they
// stand, in whatever order its components were written.
std::vector<Sym3> take_tensor_storage(vtkDataArray* array);

// The array a volume reader writes its `tuples` voxels of `components`
// values into: six in doubles on such storage, otherwise floats where
// `as_float` says the file's numbers fit them, else doubles, on huge pages.
vtkSmartPointer<vtkDataArray> volume_array(vtkIdType tuples, int components, bool as_float);

}  // namespace hsb
