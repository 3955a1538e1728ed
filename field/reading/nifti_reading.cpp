// NIfTI-1 and NIfTI-2 diffusion tensor volumes (.nii, .nii.gz, .hdr/.img),
// through VTK's vtkNIFTIImageReader, placed in the scanner's space by the
// sform (else the qform). Which of the layouts tools write it holds, and
// the axes its tensors are in:
//  - the symmetric-matrix intent (1005, six values along the fifth
//    dimension): NIfTI's lower triangle XX XY YY XZ YZ ZZ. The standard
//    names no axes for it; its usual writer, DIPY (dipy_fit_dti
//    --nifti_tensor), fits in the axes of the b-vectors it is given, FSL's
//    voxel axes (below), so they are read so, with a warning naming
//    data.frame;
//  - MRtrix's (its `descrip` says MRtrix): XX YY ZZ XY XZ YZ, in the
//    scanner's axes, as dwi2tensor writes it;
//  - else six volumes are FSL dtifit's tensor (XX XY XZ YY YZ ZZ; DIPY's
//    default layout too), which the file does not record: data.components
//    may say otherwise. Its tensors are in FSL's voxel axes, x flipped when
//    the transform keeps handedness (FSL's radiological convention, as for
//    its bvecs).
// Tensors in voxel axes are turned into the space (field/reading/
// component_arrays.h records the rotation, the voxel axes and what was
// chosen; data.frame overrides it).
// Nine volumes are a full 3×3 (row by row) in the space, three a vector.
// Internal to field/; the file is parsed only in a child process.

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkNIFTIImageHeader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkPointData.h>

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <sstream>

#include "base/input_file.h"
#include "base/memory_budget.h"
#include "base/vec3.h"
#include "field/reading/byte_numbers.h"
#include "field/reading/component_arrays.h"
#include "field/reading/component_order.h"
#include "field/reading/data_error.h"
#include "field/reading/file_records.h"
#include "field/reading/format_reader.h"
#include "field/reading/tensor_storage.h"

namespace hsb {
namespace {

constexpr int symmetric_matrix_intent = 1005;  // NIFTI_INTENT_SYMMATRIX

// Where the header puts the voxels, read from its own bytes (through
// zlib, which reads a .nii and a .nii.gz alike): VTK turns NIfTI-1's
// float vox_offset into an integer, which for a NaN or an infinity is
// undefined. (NIfTI-2's is an integer already.)
struct VoxelPlace {
  double offset = 0.0;       // vox_offset: the voxels' first byte
  bool in_same_file = false;  // a .nii (magic n+1, n+2), not a .hdr beside its .img
};

// Nothing when the header is not one this can read: VTK then says why.
std::optional<VoxelPlace> voxel_place(const std::string& path) {
  gzFile file = gzopen(path.c_str(), "rb");
  if (!file) return std::nullopt;
  unsigned char h[540] = {};
  const int got = gzread(file, h, sizeof h);
  gzclose(file);
  if (got < 348) return std::nullopt;
  const auto magic_is = [&](std::size_t at, const char* magic) {
    return std::string(reinterpret_cast<const char*>(h) + at, 3) == magic;
  };
  for (const bool swap : {false, true}) {
    const double size = load_number<std::int32_t>(h, swap);
    if (size == 348.0)  // NIfTI-1 (or Analyze 7.5, whose .img holds the voxels)
      return VoxelPlace{load_number<float>(h + 108, swap), magic_is(344, "n+1")};
    if (size == 540.0 && got == 540) return VoxelPlace{load_number<std::int64_t>(h + 168, swap), magic_is(4, "n+2")};
  }
  return std::nullopt;
}

std::string number_text(double x) {
  std::ostringstream text;
  text.precision(17);
  text << x;
  return text.str();
}

// The voxels the header declares, against the bytes the file has and the
// memory there is, before VTK allocates them: VTK reads a file cut short
// with an error (asked for after it reads) but allocates all the header
// declares first, and reads a NaN vox_offset without one.
void check_declared_voxels(vtkNIFTIImageReader* reader, const std::string& path) {
  vtkNIFTIImageHeader* header = reader->GetNIFTIHeader();
  const std::optional<VoxelPlace> place = voxel_place(path);
  if (!header || !place) return;
  if (!std::isfinite(place->offset) || place->offset < 0.0)
    throw DataError(path + ": its vox_offset (where its voxels start) is " + number_text(place->offset) +
                    ", no place in a file");
  // What VTK reads: the three space dimensions, time and the values of a
  // voxel (TimeAsVector), each value bitpix bits.
  double values = 1.0;
  std::string sizes;
  for (int d = 1; d <= std::min<int>(int(header->GetDim(0)), 5); ++d) {
    values *= double(header->GetDim(d));
    sizes += (d > 1 ? " × " : "") + std::to_string(header->GetDim(d));
  }
  const double bytes = values * header->GetBitPix() / 8.0;
  if (place->in_same_file && file_head(path, 2) != "\x1f\x8b") {
    std::error_code error;
    const double size = double(std::filesystem::file_size(path, error));
    if (!error && place->offset > size)
      throw DataError(path + ": its voxels start at byte " + number_text(place->offset) +
                      " (its vox_offset), past the file's end at " + number_text(size));
    if (!error && place->offset + bytes > size)
      throw DataError(path + ": the file is cut short: its header declares " + sizes + " values of " +
                      std::to_string(header->GetBitPix() / 8) + " bytes from byte " + number_text(place->offset) +
                      ", " + number_text(bytes) + " bytes; the file has " + number_text(size - place->offset));
  }
  // VTK's volume, and this reader's copy in doubles at most.
  check_memory(bytes + values * 8.0, path + ": its voxels (" + sizes + " values, as its header declares)",
               "a header that declares more voxels than its file holds is corrupt; else read the volume where more "
               "memory is free");
}

// The volume in `path`. Throws DataError for a file VTK cannot read (or
// reports an error for: one cut short reads as zeros otherwise), and for
// one whose voxels are not 3, 6 or 9 values.
// With `scalar`, a volume of one value per voxel (a mask) instead.
vtkSmartPointer<vtkImageData> read_nifti(const std::string& path, bool scalar, const VtkSession& vtk) {
  auto reader = vtkSmartPointer<vtkNIFTIImageReader>::New();
  if (!reader->CanReadFile(path.c_str()))
    throw DataError(path + ": not a NIfTI file: no NIfTI-1 or NIfTI-2 header (magic \"n+1\", \"ni1\", \"n+2\") in it");
  reader->SetFileName(path.c_str());
  reader->TimeAsVectorOn();  // FSL's six volumes along the fourth dimension
  // Its warnings are the file's own choices ("SFormMatrix is flipped
  // compared to QFormMatrix"), no damage: only errors refuse it.
  reader->UpdateInformation();
  vtk.refuse_complaints(path, "NIfTI", false);
  check_declared_voxels(reader, path);
  update_reader(reader, vtk, path, "NIfTI", false);
  vtkImageData* read = reader->GetOutput();
  vtkNIFTIImageHeader* header = reader->GetNIFTIHeader();
  vtkDataArray* voxels = read && header ? read->GetPointData()->GetScalars() : nullptr;
  if (!voxels || voxels->GetNumberOfTuples() == 0) throw DataError(path + ": VTK's NIfTI reader found no voxels in it");
  const int values = voxels->GetNumberOfComponents();
  if (scalar && values != 1)
    throw DataError(path + ": its voxels hold " + std::to_string(values) +
                    " values; a mask is a volume of one value per voxel");
  if (!scalar && values == 1)
    throw DataError(path + ": its voxels hold one value: a mask or a scalar map, no tensors (6 values along the "
                    "fourth or fifth dimension); a mask is given as region.mask, beside the tensors' file");
  if (!scalar && values != 3 && values != 6 && values != 9)
    throw DataError(path + ": its voxels hold " + std::to_string(values) +
                    " values; a tensor volume has 6 (or 9, or 3 for vectors) along its fourth or fifth dimension");

  // Where the voxels are: VTK's data coordinates (origin + index × spacing)
  // through the sform, else the qform, into the scanner's space; a scale
  // in the matrix goes into the spacing.
  vtkMatrix4x4* to_space = header->GetSFormCode() > 0 && reader->GetSFormMatrix() ? reader->GetSFormMatrix()
                                                                                   : reader->GetQFormMatrix();
  Mat3 a = Mat3::Identity();
  Vec3 shift = Vec3::Zero();
  if (to_space)
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) a(r, c) = to_space->GetElement(r, c);
      shift[r] = to_space->GetElement(r, 3);
    }
  const double* s = read->GetSpacing();
  const double* o = read->GetOrigin();
  Vec3 spacing;
  Mat3 direction;
  for (int c = 0; c < 3; ++c) {
    const double length = a.col(c).norm();
    if (!(length > 0) || !std::isfinite(length)) throw DataError(path + ": its sform/qform matrix is singular");
    spacing[c] = std::fabs(s[c]) * length;
    direction.col(c) = a.col(c) / length * (s[c] < 0 ? -1.0 : 1.0);
  }
  const Vec3 origin = a * Vec3(o[0], o[1], o[2]) + shift;

  const double slope = reader->GetRescaleSlope() != 0.0 ? reader->GetRescaleSlope() : 1.0;
  const double intercept = reader->GetRescaleIntercept();
  const std::string descrip = header->GetDescrip() ? header->GetDescrip() : "";
  const bool lower_triangle = values == 6 && header->GetIntentCode() == symmetric_matrix_intent;
  const bool mrtrix = values == 6 && !lower_triangle && descrip.rfind("MRtrix", 0) == 0;
  // A layout the file records is turned into VTK's here; FSL's is not recorded (below).
  const ComponentOrder* recorded = lower_triangle ? component_order("nifti") : mrtrix ? component_order("mrtrix") : nullptr;

  // Floats where the file's numbers are (FSL's and MRtrix's tensors are)
  // and no rescaling changes them: the reading child hands the volume over
  // through a file, and a double copy of float data was half of it (an
  // HCP-sized tensor volume, 3.7 million voxels: 176 MB against 88 MB).
  // Otherwise doubles, six components straight into the field's own
  // storage (tensor_storage.h) when read in this process.
  const bool as_float = voxels->GetDataType() == VTK_FLOAT && slope == 1.0 && intercept == 0.0;
  const vtkSmartPointer<vtkDataArray> array = volume_array(voxels->GetNumberOfTuples(), values, as_float);
  array->SetName(scalar ? "values" : values == 3 ? "vectors" : "tensors");
  std::array<double, 9> v{};
  for (vtkIdType i = 0; i < voxels->GetNumberOfTuples(); ++i) {
    for (int c = 0; c < values; ++c) v[std::size_t(c)] = voxels->GetComponent(i, c) * slope + intercept;
    if (recorded) {
      const std::array<double, 6> six = components_in_order(tensor_in_order(v.data(), *recorded), *component_order("vtk"));
      std::copy(six.begin(), six.end(), v.begin());
    }
    array->SetTuple(i, v.data());
  }

  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(read->GetExtent());
  image->SetSpacing(spacing.data());
  image->SetOrigin(origin.data());
  auto matrix = vtkSmartPointer<vtkMatrix3x3>::New();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) matrix->SetElement(r, c, direction(r, c));
  image->SetDirectionMatrix(matrix);
  // Through the sform or the qform, the world is the scanner's RAS+.
  if (header->GetSFormCode() > 0 || header->GetQFormCode() > 0)
    add_record(image->GetFieldData(), kAnatomicalFrame, {"RAS"});
  if (scalar) {
    image->GetPointData()->SetScalars(array);
    return image;
  }
  if (values == 3) {
    image->GetPointData()->SetVectors(array);
    return image;
  }
  image->GetPointData()->SetTensors(array);
  vtkFieldData* records = image->GetFieldData();
  if (lower_triangle) {
    record_component_order(records, "tensors", "NIfTI's symmetric-matrix intent: XX XY YY XZ YZ ZZ");
  } else if (mrtrix) {
    record_component_order(records, "tensors", "MRtrix's NIfTI (its description says so): XX YY ZZ XY XZ YZ");
  } else if (values == 6) {
    record_default_order(records, "tensors", "fsl",
                         "six volumes without NIfTI's symmetric-matrix intent: FSL dtifit's layout");
  }
  // The voxel axes as the file stores them (VTK reversed the slices when
  // qfac is −1), for data.frame; FSL's flip x where they keep handedness.
  const Mat3 voxel_axes = direction * Vec3(1.0, 1.0, reader->GetQFac() < 0 ? -1.0 : 1.0).asDiagonal();
  record_voxel_axes(records, "tensors", voxel_axes);
  if (mrtrix) {
    record_frame_note(records, "tensors", {"the scanner's axes, as MRtrix writes them"});
  } else if (values == 6) {
    record_tensor_frame(records, "tensors", fsl_axes(voxel_axes));
    record_frame_note(records, "tensors",
                      lower_triangle ? FrameNote{"FSL's voxel axes, as DIPY writes NIfTI's symmetric-matrix layout "
                                                 "(in its b-vectors' axes)", true}
                                     : FrameNote{"FSL's voxel axes, turned into the scanner's (FSL dtifit's and "
                                                 "DIPY's layout)"});
  } else {
    record_frame_note(records, "tensors", {"the scanner's axes"});
  }
  return image;
}

vtkSmartPointer<vtkDataSet> read_nifti_data(const std::string& path, const ReadRequest& request,
                                            const VtkSession& vtk) {
  return read_nifti(path, request.scalar, vtk);
}

// A .hdr's voxels are in the .img beside it (VTK's reader takes .img,
// else .img.gz, in either case): asked before VTK opens it (a FIFO there
// kept the reader waiting) and hashed for --skip-existing (a changed .img
// was found up to date).
std::vector<std::string> nifti_parts(const std::string& path) {
  std::string stem = path;
  if (stem.size() > 3 && (stem.compare(stem.size() - 3, 3, ".gz") == 0 || stem.compare(stem.size() - 3, 3, ".GZ") == 0))
    stem.resize(stem.size() - 3);
  const std::filesystem::path header(stem);
  std::string extension = header.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension != ".hdr") return {};
  std::vector<std::string> parts;
  for (const char* img : {".img", ".IMG", ".img.gz", ".IMG.gz"}) {
    const std::filesystem::path candidate = std::filesystem::path(header).replace_extension(img);
    std::error_code error;
    if (std::filesystem::exists(std::filesystem::symlink_status(candidate, error))) parts.push_back(candidate.string());
  }
  return parts;
}

}  // namespace

const FormatReader nifti_reader{read_nifti_data, nullptr, nifti_parts};

}  // namespace hsb
