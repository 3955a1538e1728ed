// NIfTI tensor volumes in the three layouts tools write (FSL dtifit's six
// volumes in its voxel axes, NIfTI's symmetric-matrix intent, MRtrix's),
// placed by the sform: each read back as the tensors of the space.
#include <gtest/gtest.h>

#include <zlib.h>

#include <array>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "field/reading/data_error.h"
#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

constexpr int nx = 4, ny = 3, nz = 5;

// A tensor of the space that changes along every axis.
Sym3 space_tensor(int i, int j, int k) {
  return Sym3{3.0 + i, 2.0 + 0.5 * j, 1.0 + 0.25 * k, 0.1 * i + 0.2, 0.2 * j - 0.3, 0.05 * k + 0.1};
}

// A NIfTI-1 file written byte by byte as the standard lays it out: float
// voxels, `dim` as given, the sform `rows` (3×4), `values(i, j, k)` the
// voxel's six numbers in the file's layout, stored as (value − intercept)
// / slope for the reader to scale back.
std::string write_nifti(const std::string& name, std::array<std::int16_t, 8> dim, std::int16_t intent,
                        const std::string& descrip, const std::array<std::array<float, 4>, 3>& rows,
                        const std::function<std::array<double, 6>(int, int, int)>& values, float slope = 1.0f,
                        float intercept = 0.0f) {
  std::vector<char> header(352, '\0');
  const auto put = [&](std::size_t at, const auto& v) { std::memcpy(header.data() + at, &v, sizeof v); };
  put(0, std::int32_t(348));
  for (int d = 0; d < 8; ++d) put(40 + 2 * std::size_t(d), dim[std::size_t(d)]);
  put(68, intent);
  put(70, std::int16_t(16));  // float32
  put(72, std::int16_t(32));
  const float pixdim[8] = {1, 1, 1, 1, 1, 1, 1, 1};
  std::memcpy(header.data() + 76, pixdim, sizeof pixdim);
  put(108, 352.0f);
  put(112, slope);
  put(116, intercept);
  std::memcpy(header.data() + 148, descrip.data(), std::min<std::size_t>(descrip.size(), 79));
  put(254, std::int16_t(1));  // sform_code: scanner
  for (int r = 0; r < 3; ++r) std::memcpy(header.data() + 280 + 16 * std::size_t(r), rows[std::size_t(r)].data(), 16);
  std::memcpy(header.data() + 344, "n+1\0", 4);
  std::vector<float> data(std::size_t(nx * ny * nz * 6));
  for (int c = 0; c < 6; ++c)
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          data[std::size_t(((c * nz + k) * ny + j) * nx + i)] =
              float((values(i, j, k)[std::size_t(c)] - intercept) / slope);
  const std::string path = (test_temp_dir("nifti") / name).string();
  std::ofstream out(path, std::ios::binary);
  out.write(header.data(), std::streamsize(header.size()));
  out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size() * sizeof(float)));
  return path;
}

void expect_space_tensors(const std::string& path, const std::function<Vec3(int, int, int)>& place) {
  const VtkData data = load_vtk_data({path});
  ASSERT_TRUE(data.field);
  for (const auto& [i, j, k] : {std::array{1, 1, 1}, std::array{3, 2, 4}, std::array{2, 0, 3}}) {
    const std::optional<Sym3> s = data.field->sample(place(i, j, k));
    ASSERT_TRUE(s) << i << j << k;
    EXPECT_LT((s->matrix() - space_tensor(i, j, k).matrix()).norm(), 1e-5) << i << " " << j << " " << k;
  }
}

// Voxel axes turned 90° about z in the space: i runs along +y, j along −x.
const std::array<std::array<float, 4>, 3> turned{{{0, -2, 0, 10}, {2, 0, 0, 20}, {0, 0, 1, 30}}};
Vec3 turned_place(int i, int j, int k) { return Vec3(10 - 2 * j, 20 + 2 * i, 30 + k); }
Mat3 turned_axes() {
  Mat3 r;
  r << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return r;
}

// FSL's voxel axes for the space's tensor S: F Rᵀ S R F, with R the voxel
// axes and F = diag(−1, 1, 1), as `turned` keeps handedness.
Mat3 to_fsl() { return Vec3(-1, 1, 1).asDiagonal() * turned_axes().transpose(); }

// NIfTI's symmetric-matrix intent as DIPY writes it (dipy_fit_dti
// --nifti_tensor): the lower triangle, in the b-vectors' axes, FSL's.
TEST(NiftiReading, SymmetricMatrixIntentIsTheLowerTriangleInFslAxesAsDipyWritesIt) {
  const std::string path = write_nifti("intent.nii", {5, nx, ny, nz, 1, 6, 1, 1}, 1005, "", turned, [](int i, int j, int k) {
    const Mat3 m = to_fsl() * space_tensor(i, j, k).matrix() * to_fsl().transpose();
    return std::array<double, 6>{m(0, 0), m(1, 0), m(1, 1), m(2, 0), m(2, 1), m(2, 2)};
  });
  expect_space_tensors(path, turned_place);
  const std::string described = describe_vtk_file({path});
  EXPECT_NE(described.find("order     recorded in the file: NIfTI's symmetric-matrix intent"), std::string::npos);
  EXPECT_NE(described.find("frame     FSL's voxel axes, as DIPY writes"), std::string::npos) << described;
  // The file does not say its axes: the choice is a warning with its key.
  const VtkData data = load_vtk_data({path});
  ASSERT_EQ(data.warnings.size(), 1u);
  EXPECT_NE(data.warnings[0].find("set data.frame"), std::string::npos) << data.warnings[0];
  // Placed by its sform, the world is the scanner's RAS+.
  EXPECT_EQ(data.anatomical_frame, "RAS");
}

// data.frame names the axes where the file's writer used others: the
// scanner's ("world"), the voxel axes as stored, or FSL's.
TEST(NiftiReading, DataFrameNamesTheTensorsAxes) {
  const auto lower = [](const Mat3& m) { return std::array<double, 6>{m(0, 0), m(1, 0), m(1, 1), m(2, 0), m(2, 1), m(2, 2)}; };
  const std::string world = write_nifti("world.nii", {5, nx, ny, nz, 1, 6, 1, 1}, 1005, "", turned,
                                        [&](int i, int j, int k) { return lower(space_tensor(i, j, k).matrix()); });
  VtkFileSpec spec{world};
  spec.frame = TensorFrame::world;
  ASSERT_TRUE(load_vtk_data(spec).warnings.empty());
  const auto expect_read_as_space = [](const VtkFileSpec& read) {
    const VtkData data = load_vtk_data(read);
    const std::optional<Sym3> s = data.field->sample(turned_place(1, 1, 1));
    ASSERT_TRUE(s);
    EXPECT_LT((s->matrix() - space_tensor(1, 1, 1).matrix()).norm(), 1e-5);
  };
  expect_read_as_space(spec);
  const Mat3 to_voxel = turned_axes().transpose();
  spec.path = write_nifti("voxel.nii", {5, nx, ny, nz, 1, 6, 1, 1}, 1005, "", turned, [&](int i, int j, int k) {
    return lower(to_voxel * space_tensor(i, j, k).matrix() * to_voxel.transpose());
  });
  spec.frame = TensorFrame::voxel;
  expect_read_as_space(spec);
  // Read in the wrong axes, the same file gives other tensors.
  spec.frame = TensorFrame::fsl;
  const std::optional<Sym3> wrong = load_vtk_data(spec).field->sample(turned_place(1, 1, 1));
  ASSERT_TRUE(wrong);
  EXPECT_GT((wrong->matrix() - space_tensor(1, 1, 1).matrix()).norm(), 0.1);
}

// Float voxels are read as floats, scaled ones (scl_slope, scl_inter) as
// the doubles their scaling makes: both come back as the space's tensors.
TEST(NiftiReading, RescaledVoxelsAreTheirScaledValues) {
  const auto lower_triangle = [](int i, int j, int k) {
    const Mat3 m = to_fsl() * space_tensor(i, j, k).matrix() * to_fsl().transpose();
    return std::array<double, 6>{m(0, 0), m(1, 0), m(1, 1), m(2, 0), m(2, 1), m(2, 2)};
  };
  expect_space_tensors(write_nifti("scaled.nii", {5, nx, ny, nz, 1, 6, 1, 1}, 1005, "", turned, lower_triangle, 0.25f,
                                   -1.5f),
                       turned_place);
}

TEST(NiftiReading, MrtrixSaysSoInItsDescription) {
  const std::string path = write_nifti("mrtrix.nii", {4, nx, ny, nz, 6, 1, 1, 1}, 0, "MRtrix version: 3.0.4", turned,
                                       [](int i, int j, int k) {
                                         const Sym3 s = space_tensor(i, j, k);
                                         return std::array<double, 6>{s.xx, s.yy, s.zz, s.xy, s.xz, s.yz};
                                       });
  expect_space_tensors(path, turned_place);
}

// FSL's dtifit: XX XY XZ YY YZ ZZ in its voxel axes, x flipped because
// this transform keeps handedness: the space's tensor S is written as
// F Rᵀ S R F, with R the voxel axes and F = diag(−1, 1, 1).
TEST(NiftiReading, FslSixVolumesAreTurnedFromItsVoxelAxes) {
  const std::string path = write_nifti("dti_tensor.nii", {4, nx, ny, nz, 6, 1, 1, 1}, 0, "FSL6.0", turned,
                                       [&](int i, int j, int k) {
                                         const Mat3 m = to_fsl() * space_tensor(i, j, k).matrix() * to_fsl().transpose();
                                         return std::array<double, 6>{m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)};
                                       });
  expect_space_tensors(path, turned_place);
  const std::string described = describe_vtk_file({path});
  EXPECT_NE(described.find("data.components = \"fsl\""), std::string::npos) << described;
  EXPECT_NE(described.find("FSL dtifit's layout"), std::string::npos) << described;
  // Another order may be named for such a file: it is not recorded.
  VtkFileSpec mrtrix{path};
  mrtrix.components = "mrtrix";
  EXPECT_NO_THROW(load_vtk_data(mrtrix));
}

TEST(NiftiReading, VoxelsOfOtherSizesAreSaidSo) {
  const std::string path = write_nifti("five.nii", {4, nx, ny, nz, 5, 1, 1, 1}, 0, "", turned,
                                       [](int, int, int) { return std::array<double, 6>{}; });
  try {
    load_vtk_data({path});
    FAIL() << "read a volume of 5 values per voxel";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("its voxels hold 5 values"), std::string::npos) << e.what();
  }
}

// A mask (FSL's nodif_brain_mask, a region of interest): one value per
// voxel, placed by the same sform as the tensors beside it.
TEST(NiftiReading, AMaskIsOneValuePerVoxelPlacedAsTheTensors) {
  const auto code = [](int i, int j, int k) { return 100.0 * i + 10.0 * j + k; };
  const std::string path = write_nifti("mask.nii", {3, nx, ny, nz, 1, 1, 1, 1}, 0, "", turned,
                                       [&](int i, int j, int k) { return std::array<double, 6>{code(i, j, k)}; });
  const std::unique_ptr<ScalarField> mask = load_mask(path);
  for (const auto& [i, j, k] : {std::array{1, 1, 1}, std::array{3, 2, 4}, std::array{2, 0, 3}, std::array{0, 2, 0}}) {
    const std::optional<double> value = mask->sample(turned_place(i, j, k));
    ASSERT_TRUE(value) << i << j << k;
    EXPECT_NEAR(*value, code(i, j, k), 1e-9) << i << " " << j << " " << k;
  }
  // Between voxels, interpolated.
  EXPECT_NEAR(*mask->sample(0.5 * (turned_place(1, 1, 1) + turned_place(2, 1, 1))), 0.5 * (code(1, 1, 1) + code(2, 1, 1)),
              1e-9);
  const std::string tensors = write_nifti("not_a_mask.nii", {4, nx, ny, nz, 6, 1, 1, 1}, 0, "", turned,
                                          [](int, int, int) { return std::array<double, 6>{1, 1, 1, 0, 0, 0}; });
  try {
    load_mask(tensors);
    FAIL() << "read a tensor volume as a mask";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("its voxels hold 6 values; a mask is a volume of one value per voxel"),
              std::string::npos)
        << e.what();
  }
}

// The bytes of a file.
std::string contents_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// `bytes` as gzip writes them (what a .nii.gz is), stored rather than
// compressed, so that a cut falls where the test says.
std::string gzipped(const std::string& bytes) {
  z_stream z{};
  deflateInit2(&z, Z_NO_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
  std::string packed(deflateBound(&z, uLong(bytes.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = uInt(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(packed.data());
  z.avail_out = uInt(packed.size());
  deflate(&z, Z_FINISH);
  packed.resize(z.total_out);
  deflateEnd(&z);
  return packed;
}

// A file that holds less than its header declares is refused, never read
// as the zeros VTK leaves where it read nothing: a header alone, half the
// voxels, a .nii.gz cut short, and voxels said to start past the end or at
// no place at all (vox_offset NaN).
TEST(NiftiReading, AFileWithoutTheVoxelsItsHeaderDeclaresIsRefused) {
  const auto tensors = [](int, int, int) { return std::array<double, 6>{2, 1, 1, 0, 0, 0}; };
  const std::string whole = contents_of(write_nifti("whole.nii", {4, nx, ny, nz, 6, 1, 1, 1}, 0, "", turned, tensors));
  ASSERT_EQ(whole.size(), 352u + std::size_t(nx * ny * nz * 6) * 4u);
  const auto refused = [](const std::string& name, const std::string& bytes, const std::string& said) {
    const std::string path = (test_temp_dir("nifti") / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    try {
      load_vtk_data({path});
      ADD_FAILURE() << name << " was read";
    } catch (const DataError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      EXPECT_NE(message.find(said), std::string::npos) << message;
    }
  };
  refused("header_alone.nii", whole.substr(0, 352), "the file is cut short");
  refused("half.nii", whole.substr(0, 352 + (whole.size() - 352) / 2), "the file is cut short");
  // Cut two thirds in: the header whole, the voxels not.
  const std::string packed = gzipped(whole);
  refused("cut.nii.gz", packed.substr(0, packed.size() * 2 / 3), "cannot read it as NIfTI");
  const auto with_offset = [&](float offset) {
    std::string bytes = whole;
    std::memcpy(&bytes[108], &offset, sizeof offset);
    return bytes;
  };
  refused("past_the_end.nii", with_offset(1e6f), "past the file's end");
  refused("no_place.nii", with_offset(std::numeric_limits<float>::quiet_NaN()), "its vox_offset");
}

}  // namespace
}  // namespace hsb
