#pragma once
// NIfTI-1 and NIfTI-2 diffusion tensor volumes (.nii, .nii.gz, .hdr/.img),
// through VTK's vtkNIFTIImageReader, placed in the scanner's space by the
// sform (else the qform). Which of the layouts tools write it holds:
//  - the symmetric-matrix intent (1005, six values along the fifth
//    dimension): NIfTI's lower triangle XX XY YY XZ YZ ZZ, in the space;
//  - MRtrix's (its `descrip` says MRtrix): XX YY ZZ XY XZ YZ, in the space;
//  - else six volumes are FSL dtifit's tensor (XX XY XZ YY YZ ZZ), which
//    the file does not record: data.components may say otherwise. FSL's
//    tensors are in its voxel axes, x flipped when the transform keeps
//    handedness (FSL's radiological convention, as for its bvecs), and
//    are turned into the space (field/reading/component_arrays.h records that).
// Nine volumes are a full 3×3 (row by row) in the space, three a vector.
// Internal to field/; the file is parsed only in a child process.

#include <string>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

namespace hsb {

// The volume in `path`. Throws DataError for a file VTK cannot read or
// whose voxels are not 3, 6 or 9 values.
vtkSmartPointer<vtkImageData> read_nifti(const std::string& path);

}  // namespace hsb
