#pragma once
// Tensors and vectors written one component per array, as Exodus files
// (stress_xx, stress_yy, ...), Abaqus exports (S11, S22, ...) and many
// solvers' VTK output store them, joined into one array in VTK's order, so
// that the array choice (field/reading/vtk_data.cpp) sees one tensor named
// "stress" and never mistakes its components for scalars, or a plane
// stress's three for a vector. The order of a joined array, or of one a
// reader converted from a layout its format records (NRRD, NIfTI), is
// recorded with the data set, for data.components and `hsb info`.
// Internal to field/.

#include <optional>
#include <string>
#include <vector>

#include "base/vec3.h"

class vtkDataSet;
class vtkDataSetAttributes;
class vtkFieldData;

namespace hsb {

// Joins, in `attributes`, every set of one-component arrays whose names
// differ only in a component suffix, case aside and with or without a
// separator before it (stress_xx, stressXX, S11):
//  - a tensor needs xx, yy and xy (11, 22, 12); a missing zz, yz or xz is
//    zero (plane data), and yx, zx, zy beside xy, xz, yz make a full 3×3
//    (9 components, row by row); otherwise 6 in VTK's order XX YY ZZ XY YZ XZ;
//  - a vector needs x and y; a missing z is zero.
// A joined array is named by the common prefix without its separator
// ("stress"), replaces its components, and has its order recorded in
// `records`. A set whose name is taken already is left as it is.
void join_component_arrays(vtkDataSetAttributes* attributes, vtkFieldData* records);

// How much an array's name says it is what a stress picture wants: 0 for
// stress (stress, sigma, S; Code_Aster's SIEF_*, SIGM_*), 1 for strain
// (strain, eps, E; Code_Aster's EPSI_*), 2 for neither.
// The rule that picks among several arrays of tensors.
int tensor_name_rank(const std::string& name);

// Records that the array `name` of `data` is in VTK's order because the
// file said which component is which (`how`: "named components stress_xx,
// ..." or the format's layout): data.components then has nothing to say.
void record_component_order(vtkFieldData* records, const std::string& name, const std::string& how);

// What record_component_order() said of `name`, "" if nothing.
std::string recorded_component_order(vtkDataSet* data, const std::string& name);

// Records how `name` of `data` was read where the file leaves the reading
// open (`note` completes "array NAME ..."): said as a warning with every
// picture of it.
void record_reading_note(vtkFieldData* records, const std::string& name, const std::string& note);
// What record_reading_note() said of `name`, "" if nothing.
std::string recorded_reading_note(vtkDataSet* data, const std::string& name);

// For a 6-component array whose order the file does not record but its
// format implies (FSL's for a NIfTI of six volumes): the data.components
// name used when the scene gives none, and why.
void record_default_order(vtkFieldData* records, const std::string& name, const std::string& order,
                          const std::string& why);
struct DefaultOrder {
  std::string order, why;  // empty when none was recorded
};
DefaultOrder recorded_default_order(vtkDataSet* data, const std::string& name);

// Records the order a file's writer implies for its 6-component arrays
// where the file records none: SfePy's output (it leaves its arrays
// node_groups and mat_id in every file it writes) stores 11 22 33 12 13 23,
// read as VTK's it would swap σyz and σxz without a sign; so does
// Code_Aster in its fields SIEF_*, SIGM_* and EPSI_* (SIXX SIYY SIZZ SIXY
// SIXZ SIYZ), whose names meshio and ParaView keep.
void record_writer_orders(vtkDataSet* data);

// The rotation (or reflection) that takes `name`'s tensors from the axes
// they were written in to the data's space: T → F T Fᵀ, after the order.
void record_tensor_frame(vtkFieldData* records, const std::string& name, const Mat3& frame);
std::optional<Mat3> recorded_tensor_frame(vtkDataSet* data, const std::string& name);

// A volume's voxel axes as its file stores them (columns: the i, j, k
// directions; NIfTI's slices may run against VTK's), from which
// data.frame = "voxel" or "fsl" turns `name`'s tensors. Where none is
// recorded, an image's direction matrix stands for them.
void record_voxel_axes(vtkFieldData* records, const std::string& name, const Mat3& axes);
std::optional<Mat3> recorded_voxel_axes(vtkDataSet* data, const std::string& name);

// FSL's voxel axes from the stored ones: i reversed where they keep
// handedness (FSL's radiological convention, as for its b-vectors).
Mat3 fsl_axes(const Mat3& voxel_axes);

// In words, the axes `name`'s tensors were read in ("FSL's voxel axes:
// dtifit's layout"), for `hsb info`; with `guess`, the file does not say
// and the reader chose: a warning names data.frame.
struct FrameNote {
  std::string text;
  bool guess = false;
};
void record_frame_note(vtkFieldData* records, const std::string& name, const FrameNote& note);
FrameNote recorded_frame_note(vtkDataSet* data, const std::string& name);

}  // namespace hsb
