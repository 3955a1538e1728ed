#pragma once
// Tensor data from VTK files: legacy .vtk (ASCII or binary) and XML .vti,
// .vtu, .vts, .vtr (ASCII, binary, appended, zlib-compressed), read by VTK's
// own readers. No VTK type appears in this header.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/shared_values.h"
#include "field/data_quantity.h"
#include "field/glyphs/triangle_mesh.h"
#include "field/reading/data_arrays.h"
#include "field/reading/site_positions.h"
#include "field/sampling/field.h"

namespace hsb {

enum class TensorAssociation {
  automatic,  // point data if the array is there, else cell data
  point,
  cell,
};

// How cell-data tensors are sampled.
enum class CellTensors {
  constant,  // piecewise constant: the tensor of the containing cell
  averaged,  // averaged onto the points (VTK's cell-data-to-point-data), then
             // interpolated like point data
};

// What the data file is read as.
enum class FieldKind {
  automatic,  // tensors if the file has them, else vectors
  tensor,
  vector,
};

// The axes a volume's tensors are written in, turned into the data's space
// (the scanner's, for a scan) when read.
enum class TensorFrame {
  automatic,  // the format's or layout's own (field/reading/component_arrays.h: record_tensor_frame)
  world,      // the data's space itself: MRtrix's, NRRD's without a measurement frame
  voxel,      // the volume's i, j, k axes as stored
  fsl,        // FSL's voxel axes: i reversed where the transform keeps handedness
              // (dtifit's, and DIPY's, which fits in its b-vectors' axes)
};

struct VtkFileSpec {
  std::string path;
  std::string array;  // "" = the active tensors (or vectors), or the only such array
  TensorAssociation association = TensorAssociation::automatic;
  CellTensors cell_tensors = CellTensors::constant;
  FieldKind kind = FieldKind::automatic;
  std::string color_array;  // a scalar array to colour by; "" = none
  std::string mask_array;   // a scalar array the picture keeps to (region.mask); "" = none
  int step = -1;            // of a time series: the step's index (-1: the first)
  std::string block;        // of a file of blocks: one, by name or index ("": all, merged)
  bool sites = false;       // also hand back the array's values where they stand (VtkData::sites)
  bool boundary = true;     // extract the data set's outer surface (VtkData::boundary)
  // The order of 6 components (field/reading/component_order.h); "" = the order
  // the file records (field/reading/component_arrays.h), else VTK's.
  std::string components;
  // The axes a volume's tensors are written in (TensorFrame).
  TensorFrame frame = TensorFrame::automatic;
  // What the tensors are; automatic: recognised from them (field/data_quantity.h).
  std::optional<DataQuantity> quantity;
  // Data already in memory (field/reading/data_arrays.h): read from these
  // arrays instead of a file, `path` only naming them in messages.
  std::shared_ptr<const DataArrays> arrays;
};

// The drawn array's values where they stand: its points, or its cells'
// centres for cell data. For a glyph at each (glyphs.placement = "points").
struct DataSites {
  SitePositions positions;
  SharedValues<Sym3> tensors;  // tensor data (the field's own, not a copy); or
  std::vector<Vec3> vectors;   // vector data
  std::vector<double> colors;  // VtkFileSpec::color_array at each, when named (NaN: none there)
};

struct VtkData {
  std::unique_ptr<TensorField> field;     // tensor data; or
  std::unique_ptr<VectorField> vectors;   // vector data
  std::unique_ptr<ScalarField> color;     // VtkFileSpec::color_array, when named
  std::unique_ptr<ScalarField> mask;      // VtkFileSpec::mask_array, when named
  TriangleMesh boundary;              // the data set's outer surface
  // A 2-D result (field/reading/plane_data.h): the axis of its plane's normal.
  std::optional<int> plane_axis;
  std::vector<std::string> warnings;  // e.g. a non-symmetric tensor array
  // The anatomical directions the axes point to ("RAS", "LPS"; file_records.h),
  // where the format says; "" elsewhere.
  std::string anatomical_frame;
  // Filled when VtkFileSpec::sites asks, and always for data without
  // volume, which has nothing else to show.
  DataSites sites;
  // Why the data has no volume to sample in between its points (a point
  // cloud, lines, a curved shell); "" when it has. The fields then sample
  // nothing, and the sites are the data.
  std::string no_volume;
  // The tensors' quantity, given or recognised; none for vectors.
  std::optional<DataQuantity> quantity;
};

// Reads the file and its tensors, or its vectors (3 components, read as
// they are), and the colour array. Tensors with 9 components are replaced by
// their symmetric part (paper eq. 2), with one warning giving the largest
// asymmetry; 6 components are read in VTK's order XX, YY, ZZ, XY, YZ, XZ.
// Throws DataError naming the file (and point or cell) for an unreadable
// file, a missing array (listing those present), a wrong component count or
// a non-finite value. Uniform image data with point tensors is sampled
// trilinearly; any other data set through a cell locator and the cells' own
// interpolation functions.
VtkData load_vtk_data(const VtkFileSpec& spec);

// A mask in a file of its own (region.mask = FILE), sampled as the data
// is: its one scalar array (the active scalars, else the only array of
// one value per point, else per cell). NIfTI and NRRD masks are volumes
// of one value per voxel, placed as the formats place their tensors.
// Throws DataError naming the file for one without volume or such array.
std::unique_ptr<ScalarField> load_mask(const std::string& path);

// Each VTK step first runs in a child process (a corrupt file crashes or
// hangs VTK's readers); a child that takes longer than `seconds` plus a
// second per megabyte of file calls the file corrupt. 30 s unless set: the
// data fuzzer sets a few, so that a file that hangs VTK costs it little.
void set_trial_read_seconds(double seconds);

// The times of the steps of a time series (a .pvd), in order; none for a
// data file of one step. Throws DataError for a series it cannot read.
// Like data_files_read(), it opens a VTK session of its own: not to be
// called while holding one.
std::vector<double> series_times(const std::string& path);

// Every file reading `path` (at `step` of a series) reads: itself, and a
// series' step, a parallel file's pieces, a multiblock file's blocks.
// Throws DataError for a series it cannot read.
std::vector<std::string> data_files_read(const std::string& path, int step = -1);

// What `hsb info` prints for a data file: kind, bounds, cell types and
// counts, arrays, and the range of each eigenvalue of the chosen tensors.
std::string describe_vtk_file(const VtkFileSpec& spec);

}  // namespace hsb
