// MRtrix images (.mif, .mif.gz, .mih with its data) as dwi2tensor and
// mrconvert write them: an oblique transform, layouts that store an axis
// in reverse or the volume axis fastest, gzip, scaling, a mask of bits; each
// read back as the space's tensors at their places. A file mrconvert wrote
// gives what the NIfTI it came from holds. What is wrong is one DataError
// naming the file and the header line.
#include <gtest/gtest.h>

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "field/reading/data_error.h"
#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

constexpr int nx = 4, ny = 3, nz = 5;

// A tensor of the space that changes along every axis, each component a
// multiple of 0.05 (exact in a scaled Int16).
Sym3 space_tensor(int i, int j, int k) {
  return Sym3{3.0 + i, 2.0 + 0.5 * j, 1.0 + 0.25 * k, 0.1 * i + 0.2, 0.2 * j - 0.3, 0.05 * k + 0.1};
}

// dwi2tensor's order: D11 D22 D33 D12 D13 D23.
std::array<double, 6> mrtrix_components(const Sym3& s) { return {s.xx, s.yy, s.zz, s.xy, s.xz, s.yz}; }

// An oblique transform with unit columns (30° about z, then 20° about x),
// the voxel sizes apart, as MRtrix writes it.
const double vox[3] = {2.0, 2.5, 1.5};
Mat3 rotation() {
  const double degree = 3.14159265358979323846 / 180;
  const double a = 30 * degree, b = 20 * degree;
  Mat3 z, x;
  z << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  x << 1, 0, 0, 0, std::cos(b), -std::sin(b), 0, std::sin(b), std::cos(b);
  return z * x;
}
const Vec3 shift(-10.0, 20.0, 5.5);
Vec3 oblique_place(int i, int j, int k) { return rotation() * Vec3(i * vox[0], j * vox[1], k * vox[2]) + shift; }

std::string header_lines(const std::string& dim, const std::string& layout, const std::string& datatype,
                         const std::string& extra) {
  std::string text = "mrtrix image\ndim: " + dim + "\nvox: 2,2.5,1.5,nan\nlayout: " + layout +
                     "\ndatatype: " + datatype + "\n";
  char row[200];
  for (int r = 0; r < 3; ++r) {
    std::snprintf(row, sizeof row, "transform: %.17g, %.17g, %.17g, %.17g\n", rotation()(r, 0), rotation()(r, 1),
                  rotation()(r, 2), shift[r]);
    text += row;
  }
  return text + "command_history: written by a test  # a comment\nmrtrix_version: 3.0.4\n" + extra;
}

// One axis of the nested loops that lay the data out, slowest first.
struct Loop {
  int axis;
  bool reversed = false;
};

// The layout the loops make: each axis's rank from the fastest, a minus
// where it runs from its last voxel to its first.
std::string layout_of(const std::vector<Loop>& slow_to_fast) {
  std::string ranks[4];
  for (std::size_t p = 0; p < slow_to_fast.size(); ++p)
    ranks[slow_to_fast[p].axis] = (slow_to_fast[p].reversed ? "-" : "+") + std::to_string(slow_to_fast.size() - 1 - p);
  std::string text;
  for (std::size_t a = 0; a < slow_to_fast.size(); ++a) text += (a ? "," : "") + ranks[a];
  return text;
}

// value(i, j, k, c) in the order of the nested loops: written as the
// layout says, without the reader's stride arithmetic.
std::vector<double> in_file_order(const std::vector<Loop>& slow_to_fast, const std::array<int, 4>& sizes,
                                  const std::function<double(int, int, int, int)>& value) {
  std::vector<double> out;
  std::array<int, 4> at{};
  const std::function<void(std::size_t)> loop = [&](std::size_t p) {
    if (p == slow_to_fast.size()) {
      out.push_back(value(at[0], at[1], at[2], at[3]));
      return;
    }
    const Loop l = slow_to_fast[p];
    for (int n = 0; n < sizes[std::size_t(l.axis)]; ++n) {
      at[std::size_t(l.axis)] = l.reversed ? sizes[std::size_t(l.axis)] - 1 - n : n;
      loop(p + 1);
    }
  };
  loop(0);
  return out;
}

template <typename T>
std::string bytes_of(const std::vector<double>& values, bool big_endian) {
  std::string out(values.size() * sizeof(T), '\0');
  for (std::size_t i = 0; i < values.size(); ++i) {
    const T t = T(values[i]);
    char b[sizeof(T)];
    std::memcpy(b, &t, sizeof(T));
    if (big_endian) std::reverse(b, b + sizeof(T));
    std::memcpy(&out[i * sizeof(T)], b, sizeof(T));
  }
  return out;
}

// A header and its data in one file, at the offset MRtrix would choose
// (after "file: . N" and END, on a 4-byte boundary).
std::string with_data(const std::string& head, const std::string& data) {
  std::size_t offset = head.size() + 24;
  offset += (4 - offset % 4) % 4;
  std::string text = head + "file: . " + std::to_string(offset) + "\nEND\n";
  text.resize(offset, '\0');
  return text + data;
}

std::string write_file(const std::string& name, const std::string& content) {
  const std::string path = (test_temp_dir("mif") / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// The whole file gzip-compressed, as mrconvert writes a .mif.gz. With
// `flushed`, the compressed bytes that inflate to the first `flush_at`
// (where the stream is flushed) are counted there.
std::string write_gzip(const std::string& name, const std::string& content, std::size_t flush_at = 0,
                       long* flushed = nullptr) {
  const std::string path = (test_temp_dir("mif") / name).string();
  gzFile out = gzopen(path.c_str(), "wb");
  gzwrite(out, content.data(), unsigned(flush_at));
  gzflush(out, Z_SYNC_FLUSH);
  if (flushed) *flushed = long(gzoffset(out));
  gzwrite(out, content.data() + flush_at, unsigned(content.size() - flush_at));
  gzclose(out);
  return path;
}

// The tensor image of space_tensor, its data laid out by `loops`.
std::string tensor_image(const std::vector<Loop>& loops) {
  const std::vector<double> values = in_file_order(loops, {nx, ny, nz, 6}, [](int i, int j, int k, int c) {
    return mrtrix_components(space_tensor(i, j, k))[std::size_t(c)];
  });
  return with_data(header_lines("4,3,5,6", layout_of(loops), "Float32LE", ""), bytes_of<float>(values, false));
}

void expect_space_tensors(const std::string& path, const std::function<Vec3(int, int, int)>& place = oblique_place) {
  const VtkData data = load_vtk_data({path});
  ASSERT_TRUE(data.field);
  for (const auto& [i, j, k] : {std::array{1, 1, 1}, std::array{3, 2, 4}, std::array{2, 0, 3}, std::array{0, 1, 2}}) {
    const std::optional<Sym3> s = data.field->sample(place(i, j, k));
    ASSERT_TRUE(s) << i << j << k;
    EXPECT_LT((s->matrix() - space_tensor(i, j, k).matrix()).norm(), 1e-5) << i << " " << j << " " << k;
  }
  // MRtrix's scanner space is RAS+.
  EXPECT_EQ(data.anatomical_frame, "RAS");
}

const std::vector<std::vector<Loop>> layouts{
    {{3}, {2}, {1}, {0, true}},        // -0,+1,+2,+3: mrconvert's from a LAS NIfTI
    {{0}, {3}, {2}, {1}},              // +3,+0,+1,+2: the space axis x slowest
    {{2}, {1}, {0}, {3}},              // +1,+2,+3,+0: the volume axis fastest
    {{2, true}, {1}, {0, true}, {3}},  // -1,+2,-3,+0: that, two axes reversed
};

TEST(MifReading, ObliqueTransformInEveryLayout) {
  for (const std::vector<Loop>& loops : layouts) {
    SCOPED_TRACE(layout_of(loops));
    expect_space_tensors(write_file("tensors.mif", tensor_image(loops)));
  }
  EXPECT_EQ(layout_of(layouts[1]), "+3,+0,+1,+2");
  const std::string described = describe_vtk_file({write_file("tensors.mif", tensor_image(layouts[0]))});
  EXPECT_NE(described.find("recorded in the file: MRtrix's .mif (dwi2tensor): D11 D22 D33 D12 D13 D23"),
            std::string::npos)
      << described;
  EXPECT_NE(described.find("the scanner's axes, as MRtrix writes them"), std::string::npos) << described;
}

TEST(MifReading, GzipCompressedWhole) {
  for (const std::vector<Loop>& loops : {layouts[0], layouts[2]}) {
    SCOPED_TRACE(layout_of(loops));
    const std::string path = write_gzip("tensors.mif.gz", tensor_image(loops));
    expect_space_tensors(path);
    EXPECT_EQ(data_files_read(path).size(), 1u);
  }
}

// A .mih names its data file beside it (mrconvert's "file: NAME.dat").
TEST(MifReading, AHeaderApartFromItsData) {
  const std::vector<Loop>& loops = layouts[3];
  const std::vector<double> values = in_file_order(loops, {nx, ny, nz, 6}, [](int i, int j, int k, int c) {
    return mrtrix_components(space_tensor(i, j, k))[std::size_t(c)];
  });
  write_file("apart.dat", bytes_of<double>(values, false));
  const std::string path = write_file(
      "apart.mih", header_lines("4,3,5,6", layout_of(loops), "Float64LE", "") + "file: apart.dat 0\nEND\n");
  expect_space_tensors(path);
  const std::vector<std::string> files = data_files_read(path);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1], (test_temp_dir("mif") / "apart.dat").lexically_normal().string());
}

// value = offset + scale × stored, here big-endian 16-bit integers.
TEST(MifReading, ScalingIsApplied) {
  const double offset = -1.5, scale = 0.05;
  const std::vector<double> values = in_file_order(layouts[0], {nx, ny, nz, 6}, [&](int i, int j, int k, int c) {
    return std::round((mrtrix_components(space_tensor(i, j, k))[std::size_t(c)] - offset) / scale);
  });
  const std::string head = header_lines("4,3,5,6", layout_of(layouts[0]), "Int16BE", "scaling: -1.5,0.05\n");
  expect_space_tensors(write_file("scaled.mif", with_data(head, bytes_of<std::int16_t>(values, true))));
}

// Three values a voxel: a vector image (sh2peaks' first peak).
TEST(MifReading, ThreeValuesAreVectors) {
  const auto vector = [](int i, int j, int k) { return Vec3(1.0 + i, 0.5 * j - 1, 0.25 * k); };
  const std::vector<double> values = in_file_order(layouts[2], {nx, ny, nz, 3}, [&](int i, int j, int k, int c) {
    return vector(i, j, k)[c];
  });
  const VtkData data = load_vtk_data(
      {write_file("peaks.mif", with_data(header_lines("4,3,5,3", layout_of(layouts[2]), "Float32LE", ""),
                                         bytes_of<float>(values, false)))});
  ASSERT_TRUE(data.vectors);
  // Inside the volume: vectors are sampled through its cells, whose
  // locator need not find a point on the volume's very corner.
  for (const auto& [i, j, k] : {std::array{1, 1, 1}, std::array{2, 1, 3}}) {
    const std::optional<Vec3> v = data.vectors->sample(oblique_place(i, j, k));
    ASSERT_TRUE(v);
    EXPECT_LT((*v - vector(i, j, k)).norm(), 1e-5) << i << " " << j << " " << k;
  }
}

// A mask as dwi2mask writes it: one bit a voxel, the first in a byte's
// highest bit, placed as the tensors beside it.
TEST(MifReading, AMaskOfBits) {
  const auto inside = [](int i, int j, int k) { return (i + 2 * j + k) % 3 == 0 ? 1 : 0; };
  const std::vector<Loop> loops{{2}, {1}, {0, true}};
  const std::vector<double> bits = in_file_order(loops, {nx, ny, nz, 1}, [&](int i, int j, int k, int) {
    return inside(i, j, k);
  });
  std::string packed((bits.size() + 7) / 8, '\0');
  for (std::size_t n = 0; n < bits.size(); ++n)
    if (bits[n] != 0) packed[n / 8] = char(packed[n / 8] | (0x80 >> (n % 8)));
  const std::string path =
      write_file("mask.mif", with_data(header_lines("4,3,5", layout_of(loops), "Bit", ""), packed));
  const std::unique_ptr<ScalarField> mask = load_mask(path);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::optional<double> value = mask->sample(oblique_place(i, j, k));
        ASSERT_TRUE(value) << i << j << k;
        EXPECT_NEAR(*value, inside(i, j, k), 1e-9) << i << " " << j << " " << k;
      }
  // A mask is no tensor image, and a tensor image no mask: each said so.
  try {
    load_vtk_data({path});
    FAIL() << "read a mask as tensors";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("its voxels hold one value"), std::string::npos) << e.what();
  }
  try {
    load_mask(write_file("tensors.mif", tensor_image(layouts[0])));
    FAIL() << "read tensors as a mask";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("its voxels hold 6 values"), std::string::npos) << e.what();
  }
}

std::string message_of(const std::string& path) {
  try {
    load_vtk_data({path});
  } catch (const DataError& e) {
    return e.what();
  }
  return "no error";
}

// Each broken file is one DataError that names the file, the header line
// where it has one, and what was expected.
TEST(MifReading, WhatIsWrongIsSaidAtItsLine) {
  const std::string good = tensor_image(layouts[0]);
  const auto broken = [&](const std::string& from, const std::string& to) {
    std::string content = good;
    content.replace(content.find(from), from.size(), to);
    return write_file("broken.mif", content);
  };
  const auto expect_message = [](const std::string& path, const std::string& part) {
    const std::string said = message_of(path);
    EXPECT_NE(said.find(path), std::string::npos) << said;
    EXPECT_NE(said.find(part), std::string::npos) << said;
  };
  // Cut short: the data's size against what the header declares.
  const std::string cut = good.substr(0, good.size() - 100);
  expect_message(write_file("short.mif", cut), "the data is cut short");
  expect_message(write_file("short.mif", cut), "declares 1440 bytes; the file has 1340 from there");
  expect_message(write_gzip("short.mif.gz", cut), "the inflated file has 1340 from there");
  // A gzip stream cut short inflates to less: the same error. (Cut
  // halfway through the data's compressed bytes, after the header's.)
  long header_packed = 0;
  const std::string whole = write_gzip("whole.mif.gz", good, good.find("END\n") + 4, &header_packed);
  std::ifstream in(whole, std::ios::binary);
  const std::string packed{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  expect_message(write_file("cut.mif.gz", packed.substr(0, (std::size_t(header_packed) + packed.size()) / 2)),
                 "the data is cut short");
  // The header without its END.
  expect_message(write_file("open.mif", good.substr(0, good.find("END"))), "without its \"END\" line");
  expect_message(write_gzip("open.mif.gz", good.substr(0, good.find("file:"))), "without its \"END\" line");
  expect_message(broken("dim: 4,3,5,6", "dim: 4,-3,5,6"), ":2: \"dim:\" expects whole numbers");
  expect_message(broken("dim: 4,3,5,6", "dim: 4,3,5,6,2"), ":2: \"dim: 4,3,5,6,2\" has a fifth axis");
  expect_message(broken("dim: 4,3,5,6", "dim: 4000,3000,5000,6"), ":2: \"dim: 4000,3000,5000,6\" declares more");
  expect_message(broken("dim: 4,3,5,6", "dim: 4,3,5,5"), ":2: its voxels hold 5 values");
  expect_message(broken("layout: -0,+1,+2,+3", "layout: -0,+1,+1,+3"), ":4: \"layout: -0,+1,+1,+3\" is not a rank");
  expect_message(broken("layout: -0,+1,+2,+3", "layout: -0,+1,+2"), ":4: \"layout: -0,+1,+2\" is not a rank");
  expect_message(broken("datatype: Float32LE", "datatype: Float16LE"), ":5: \"datatype: Float16LE\" is no MRtrix");
  expect_message(broken("datatype: Float32LE", "datatype: CFloat32LE"), ":5: \"datatype: CFloat32LE\" is complex");
  expect_message(broken("vox: 2,", "vox: 0,"), ":3: \"vox:\" expects a positive size");
  expect_message(broken("transform: ", "transform: 1, "), ":6: \"transform:\" expects a row of four");
  expect_message(broken("mrtrix_version: 3.0.4\n", "file: other.dat 0\n"), "split over 2 \"file:\" entries");
  expect_message(broken("mrtrix image", "mrtrix_image"), ":1: not an MRtrix image");
  expect_message(write_file("missing.mih", good.substr(0, good.find("file:")) + "file: missing.dat\nEND\n"),
                 "cannot open its data file");
}

// A voxel of a real file: where it lies (world) and its tensor as MRtrix
// stores it, D11 D22 D33 D12 D13 D23.
struct KnownVoxel {
  Vec3 place;
  std::array<double, 6> d;
};

void expect_known_voxels(const VtkData& data, const std::vector<KnownVoxel>& voxels) {
  for (const KnownVoxel& v : voxels) {
    const std::optional<Sym3> s = data.field->sample(v.place);
    ASSERT_TRUE(s) << v.place.transpose();
    const Sym3 expected{v.d[0], v.d[1], v.d[2], v.d[3], v.d[5], v.d[4]};  // VTK's: XX YY ZZ XY YZ XZ
    EXPECT_LT((s->matrix() - expected.matrix()).norm(), 1e-12) << v.place.transpose();
  }
}

// A file mrconvert 3.0.3 wrote (tests/field/data/mrtrix_oblique.mif.gz):
// `mrconvert -strides -2,3,4,1 oblique.nii mrtrix_oblique.mif.gz` from a
// NIfTI of 5×4×3×6 float voxels, its sform an oblique LAS one (voxels
// 2×2.5×3 mm, turned 20° about z and 10° about x, i running to the left;
// mrconvert flips i to the right, stored in reverse) and its six volumes
// D11 D22 D33 D12 D13 D23 = 1.5e-3 + 1e-4 i, 1.1e-3 + 5e-5 j, 0.7e-3 +
// 2e-5 k, 1e-5 (i − j), 2e-5 (k + 1) − 1e-5 i, −3e-5 j + 1e-5 k.
// Its layout is -1,+2,+3,+0: the volume axis fastest, x reversed. The
// values are the NIfTI's (read by nibabel) at its voxels (1, 1, 1),
// (3, 2, 1) and (2, 1, 1), the .mif's (3, 1, 1), (1, 2, 1) and (2, 1, 1);
// the places, the .mif's transform applied to those (within 1e-7 mm of
// where the NIfTI's float sform puts them).
TEST(MifReading, AFileMrconvertWrote) {
  const std::string path = std::string(HSB_SOURCE_DIR) + "/tests/field/data/mrtrix_oblique.mif.gz";
  const VtkData data = load_vtk_data({path});
  ASSERT_TRUE(data.field);
  const std::vector<KnownVoxel> voxels = {
      {{9.956728077275255, -28.86002660655847, 10.638543709543432},
       {0.0015999999595806003, 0.0011500000255182385, 0.0007200000109151006, 0.0, 2.9999999242136255e-05,
        -1.9999999494757503e-05}},
      {{5.355897389640988, -27.914565778030436, 11.07266416212955},
       {0.0017999999690800905, 0.0012000000569969416, 0.0007200000109151006, 9.999999747378752e-06,
        9.999999747378752e-06, -4.999999873689376e-05}},
      {{8.077342843575769, -29.544066914838865, 10.638543709543432},
       {0.0017000000225380063, 0.0011500000255182385, 0.0007200000109151006, 9.999999747378752e-06,
        1.9999999494757503e-05, -1.9999999494757503e-05}},
  };
  expect_known_voxels(data, voxels);
  EXPECT_EQ(data.anatomical_frame, "RAS");
}

// dwi2tensor's own .mif of the simulated head (scenes/data/formats,
// layout -0,+1,+2,+3 under an oblique transform, 33 prior_dw_scheme
// lines): its tensors at four voxels, in the bundles and between them,
// are the NIfTI's that mrconvert made of it (dwi_mrtrix_dt_masked.nii.gz,
// read by nibabel; the .mif's voxel i is the NIfTI's 39 − i). The places
// are the .mif's transform applied to (i, j, k) × 2.5 mm.
TEST(MifReading, Dwi2tensorsOwnFile) {
  const std::string path = std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/dwi_mrtrix_dt.mif";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
  const VtkData data = load_vtk_data({path});
  ASSERT_TRUE(data.field);
  const std::vector<KnownVoxel> voxels = {
      // the .mif's voxels (20, 26, 10), (20, 12, 9), (10, 20, 5), (30, 25, 12)
      {{5.0046096989171645, 1.4953902598689197, 22.802287421402774},
       {0.0015659071505069733, 0.0003198905033059418, 0.0002639211597852409, 0.0003243596584070474,
        0.0002206542412750423, 6.621582724619657e-05}},
      {{3.3446186822858266, -31.84461864107194, 11.988489121956011},
       {0.0003144279180560261, 0.00038939143996685743, 0.0016931340796872973, -5.28138457411842e-07,
        2.7792084438260645e-05, 0.00025157342315651476}},
      {{-22.716913095518834, -10.783086851491873, 13.474577411186424},
       {0.0013407244114205241, 0.000432369124609977, 0.000488552323076874, 0.00021714936883654445,
        0.00019620823150034994, 2.608017712191213e-05}},
      {{30.38460711973657, -1.3846072139397947, 20.85001945281412},
       {0.0007744793547317386, 0.0006855403771623969, 0.000625823566224426, 1.7015609046211466e-05,
        4.2574942199280486e-05, -7.002644269960001e-05}},
  };
  expect_known_voxels(data, voxels);
}

}  // namespace
}  // namespace hsb
