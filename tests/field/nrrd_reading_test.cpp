// NRRD volumes as Teem, Slicer and ITK write them: tensor kinds, oblique
// space directions, the measurement frame, the encodings, a detached
// header; and one clear error, at its header line, for what is wrong.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <zlib.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "base/memory_budget.h"
#include "base/process_memory.h"
#include "field/reading/data_error.h"
#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

// A tensor that changes along every axis, so that a voxel read from the
// wrong place, or a component from the wrong slot, shows.
Sym3 voxel_tensor(int i, int j, int k) {
  return Sym3{3.0 + i, 2.0 + 0.5 * j, 1.0 + 0.25 * k, 0.1 * i, 0.2 * j - 0.3, 0.05 * k + 0.1};
}

constexpr int nx = 4, ny = 3, nz = 5;

// Teem's seven values per voxel: confidence, XX XY XZ YY YZ ZZ; the voxel
// (0, 0, 0) masked out.
std::vector<float> masked_values() {
  std::vector<float> v;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Sym3 s = voxel_tensor(i, j, k);
        const float conf = i + j + k == 0 ? 0.0f : 1.0f;
        for (double x : {double(conf), s.xx, s.xy, s.xz, s.yy, s.yz, s.zz}) v.push_back(float(x));
      }
  return v;
}

std::string bytes_of(const std::vector<float>& values, bool big_endian = false) {
  std::string out(values.size() * 4, '\0');
  for (std::size_t i = 0; i < values.size(); ++i) {
    char b[4];
    std::memcpy(b, &values[i], 4);
    if (big_endian) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
    std::memcpy(&out[i * 4], b, 4);
  }
  return out;
}

std::string header(const std::string& encoding, const std::string& extra = "") {
  return "NRRD0005\n# made by a test\ntype: float\ndimension: 4\nspace: right-anterior-superior\n"
         "sizes: 7 " + std::to_string(nx) + " " + std::to_string(ny) + " " + std::to_string(nz) + "\n"
         "space directions: none (2,0,0) (0,3,0) (0,0,0.5)\nkinds: 3D-masked-symmetric-matrix space space space\n"
         "endian: little\nencoding: " + encoding + "\nspace origin: (10,20,30)\n" + extra;
}

std::string write_file(const std::string& name, const std::string& content) {
  const std::string path = (test_temp_dir("nrrd") / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// The tensor sampled at the voxel (i, j, k) of a volume placed by `place`.
void expect_voxels(const VtkData& data, const std::function<Vec3(int, int, int)>& place,
                   const Mat3& frame = Mat3::Identity()) {
  ASSERT_TRUE(data.field);
  for (const auto& [i, j, k] : {std::array{1, 1, 1}, std::array{3, 2, 4}, std::array{2, 0, 3}}) {
    const std::optional<Sym3> s = data.field->sample(place(i, j, k));
    ASSERT_TRUE(s) << i << j << k;
    const Mat3 expected = frame * voxel_tensor(i, j, k).matrix() * frame.transpose();
    EXPECT_LT((s->matrix() - expected).norm(), 1e-5) << i << " " << j << " " << k;
  }
  EXPECT_FALSE(data.field->sample(place(0, 0, 0)));  // masked: no data
}

Vec3 axis_aligned(int i, int j, int k) { return Vec3(10 + 2 * i, 20 + 3 * j, 30 + 0.5 * k); }

TEST(NrrdReading, TeemMaskedTensorsRawGzipAsciiBigEndian) {
  const std::vector<float> values = masked_values();
  std::string ascii;
  for (float v : values) ascii += std::to_string(v) + " ";
  std::string packed(compressBound(uLong(values.size() * 4)), '\0');
  uLongf packed_size = uLongf(packed.size());
  const std::string raw = bytes_of(values);
  compress(reinterpret_cast<Bytef*>(packed.data()), &packed_size, reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()));
  packed.resize(packed_size);  // zlib's own wrapper: the reader takes gzip's and zlib's
  std::string big = header("raw") + "\n" + bytes_of(values, true);
  big.replace(big.find("endian: little"), 14, "endian: big");
  for (const std::string& content : {header("raw") + "\n" + raw, header("gzip") + "\n" + packed,
                                     header("ascii") + "\n" + ascii, big}) {
    SCOPED_TRACE(content.substr(content.find("encoding"), 20));
    expect_voxels(load_vtk_data({write_file("volume.nrrd", content)}), axis_aligned);
  }
}

TEST(NrrdReading, ObliqueDirectionsAndTheMeasurementFrame) {
  // Axes turned 90° about z: i runs along +y, j along −x. The measurement
  // frame turns the tensors the same way.
  std::string content = header("raw", "measurement frame: (0,1,0) (-1,0,0) (0,0,1)\n") + "\n" + bytes_of(masked_values());
  content.replace(content.find("(2,0,0) (0,3,0)"), 15, "(0,2,0) (-3,0,0)");
  Mat3 frame;
  frame << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  expect_voxels(load_vtk_data({write_file("oblique.nrrd", content)}),
                [](int i, int j, int k) { return Vec3(10 - 3 * j, 20 + 2 * i, 30 + 0.5 * k); }, frame);
}

TEST(NrrdReading, ADetachedHeaderNamesItsData) {
  write_file("volume.raw", bytes_of(masked_values()));
  const std::string path = write_file("volume.nhdr", header("raw", "data file: volume.raw\n"));
  expect_voxels(load_vtk_data({path}), axis_aligned);
  EXPECT_EQ(data_files_read(path).size(), 2u);
}

// The space's anatomical directions reach the data (for the direction
// key's labels), in NRRD's long and short spellings; a space without
// anatomy has none.
TEST(NrrdReading, TheSpaceSaysWhereTheAxesPoint) {
  const std::string raw = bytes_of(masked_values());
  const std::string base = header("raw");
  const auto frame_of = [&](const std::string& space) {
    std::string content = base + "\n" + raw;
    content.replace(content.find("right-anterior-superior"), 23, space);
    return load_vtk_data({write_file("space.nrrd", content)}).anatomical_frame;
  };
  EXPECT_EQ(frame_of("right-anterior-superior"), "RAS");
  EXPECT_EQ(frame_of("left-posterior-superior"), "LPS");
  EXPECT_EQ(frame_of("LAS"), "LAS");
  EXPECT_EQ(frame_of("scanner-xyz"), "");
  EXPECT_EQ(frame_of("3D-right-handed"), "");
}

// Each broken header is one DataError that names the file and its line.
TEST(NrrdReading, WhatIsWrongIsSaidAtItsLine) {
  const std::string raw = bytes_of(masked_values());
  const auto broken = [&](const std::string& from, const std::string& to, bool with_data = true) {
    std::string content = header("raw") + "\n" + (with_data ? raw : raw.substr(0, 100));
    if (!from.empty()) content.replace(content.find(from), from.size(), to);
    return write_file("broken.nrrd", content);
  };
  const auto message = [](const std::string& path) {
    try {
      load_vtk_data({path});
    } catch (const DataError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(broken("sizes: 7 4", "sizes: 7 -4")).find("broken.nrrd:6: each size must be"), std::string::npos);
  EXPECT_NE(message(broken("sizes: 7 4 3 5", "sizes: 7 99999 99999 99999")).find(":6: the volume declares more"),
            std::string::npos);
  EXPECT_NE(message(broken("", "", false)).find("its raw data has"), std::string::npos);
  EXPECT_NE(message(broken("kinds: 3D-masked-symmetric-matrix", "kinds: RGB-color")).find(":8: the first axis"),
            std::string::npos);
  EXPECT_NE(message(broken("encoding: raw", "encoding: bzip2")).find("encoding \"bzip2\" is not read"), std::string::npos);
  EXPECT_NE(message(broken("type: float", "type: quaternion")).find(":3: NRRD type"), std::string::npos);
  EXPECT_NE(message(broken("(0,3,0)", "(0,3)")).find(":7: expected a vector"), std::string::npos);
  EXPECT_NE(message(broken("dimension: 4", "dimension: 3")).find("one value per voxel"), std::string::npos);
}

// A mask (a label map as 3D Slicer writes one): dimension 3, one value per
// voxel, placed by the same space directions as a tensor volume's.
TEST(NrrdReading, AMaskIsAVolumeOfOneValuePerVoxel) {
  std::vector<float> codes;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) codes.push_back(float(100 * i + 10 * j + k));
  const std::string head = "NRRD0005\ntype: float\ndimension: 3\nspace: right-anterior-superior\nsizes: " +
                           std::to_string(nx) + " " + std::to_string(ny) + " " + std::to_string(nz) +
                           "\nspace directions: (2,0,0) (0,3,0) (0,0,0.5)\nkinds: space space space\n"
                           "endian: little\nencoding: raw\nspace origin: (10,20,30)\n\n";
  const std::string path = write_file("mask.nrrd", head + bytes_of(codes));
  const std::unique_ptr<ScalarField> mask = load_mask(path);
  for (const auto& [i, j, k] : {std::array{1, 1, 1}, std::array{3, 2, 4}, std::array{0, 0, 0}}) {
    const std::optional<double> value = mask->sample(axis_aligned(i, j, k));
    ASSERT_TRUE(value) << i << j << k;
    EXPECT_NEAR(*value, 100.0 * i + 10.0 * j + k, 1e-9) << i << " " << j << " " << k;
  }
  // A tensor volume is no mask, and a mask no tensor volume: each said so.
  try {
    load_mask(write_file("tensors.nrrd", header("raw") + "\n" + bytes_of(masked_values())));
    FAIL() << "read tensors as a mask";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("a mask is a volume of one value per voxel: expected dimension 3"),
              std::string::npos)
        << e.what();
  }
  try {
    load_vtk_data({path});
    FAIL() << "read a mask as tensors";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("a volume of one value per voxel: no tensors or vectors"), std::string::npos)
        << e.what();
  }
}

// The address space this process may still map lowered to `room` more than
// it maps now (ulimit -v, which the memory budget heeds), while it lives:
// the budget made small whatever the machine's memory.
class SmallAddressSpace {
 public:
  explicit SmallAddressSpace(double room) {
    getrlimit(RLIMIT_AS, &before_);
    rlimit lowered = before_;
    lowered.rlim_cur = rlim_t(virtual_bytes() + room);
    if (before_.rlim_cur != RLIM_INFINITY) lowered.rlim_cur = std::min(lowered.rlim_cur, before_.rlim_cur);
    setrlimit(RLIMIT_AS, &lowered);
  }
  ~SmallAddressSpace() { setrlimit(RLIMIT_AS, &before_); }
  SmallAddressSpace(const SmallAddressSpace&) = delete;
  SmallAddressSpace& operator=(const SmallAddressSpace&) = delete;

 private:
  rlimit before_{};
};

// A header may declare up to 2^31 values: as doubles, 17 GB, and a small
// gzip stream may claim to inflate to them. What the read would take is
// weighed against the memory budget before anything is allocated: 2^30
// doubles in a gzip stream of a kilobyte are refused at once, not inflated
// until memory runs out (nor said to be short only once they were).
TEST(NrrdReading, AVolumeLargerThanTheMemoryBudgetIsRefusedBeforeItIsRead) {
  const std::string zeros(1 << 20, '\0');
  std::string packed(compressBound(uLong(zeros.size())), '\0');
  uLongf packed_size = uLongf(packed.size());
  compress(reinterpret_cast<Bytef*>(packed.data()), &packed_size, reinterpret_cast<const Bytef*>(zeros.data()),
           uLong(zeros.size()));
  packed.resize(packed_size);
  const std::string path =
      write_file("bomb.nrrd", "NRRD0005\ntype: double\ndimension: 4\nsizes: 7 1024 1024 146\n"
                              "kinds: 3D-masked-symmetric-matrix space space space\nendian: little\nencoding: gzip\n\n" +
                                  packed);
  const auto start = std::chrono::steady_clock::now();
  std::string message = "no error";
  {
    const SmallAddressSpace small(2e9);
    try {
      load_vtk_data({path});
    } catch (const ResourceError& e) {
      message = e.what();
    } catch (const DataError& e) {
      message = std::string("a DataError: ") + e.what();
    }
  }
  EXPECT_EQ(message.rfind(path + ": the volume its header declares (sizes 7 1024 1024 146, double values) would take "
                                 "about ",
                          0),
            0u)
      << message;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

}  // namespace
}  // namespace hsb
