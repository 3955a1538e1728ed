// VTK's HDF5 format (VTKHDF 1.0), read through vtkHDFReader: the Kirsch
// plate as h5py writes it to VTK's specification
// (scenes/data/generators/formats/vtkhdf_plate.py).

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "field/reading/data_error.h"
#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

const std::string plate = std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/kirsch_plate.vtkhdf";

TEST(VtkHdf, TheKirschPlateReadsWithItsConcentration) {
  const VtkData data = load_vtk_data({plate});
  ASSERT_TRUE(data.field);
  // Kirsch under σ = 10 along x: 3σ at the top of the hole, −σ at its side,
  // σ far from it (the array is not active: picked by its name).
  const std::optional<Sym3> top = data.field->sample(Vec3(0.0, 1.0 + 1e-3, 0.5));
  const std::optional<Sym3> side = data.field->sample(Vec3(1.0 + 1e-3, 0.0, 0.5));
  const std::optional<Sym3> far = data.field->sample(Vec3(-9.0, 4.0, 0.5));
  ASSERT_TRUE(top && side && far);
  EXPECT_NEAR(top->xx, 30.0, 1.5);
  EXPECT_NEAR(side->yy, -10.0, 1.0);
  EXPECT_NEAR(far->xx, 10.0, 0.5);
  EXPECT_NE(describe_vtk_file({plate}).find("5795 vtkTetra"), std::string::npos) << describe_vtk_file({plate});
}

TEST(VtkHdf, AnHdf5FileOfAnotherKindIsSaidSo) {
  const std::string other = (test_temp_dir("vtkhdf") / "other.vtkhdf").string();
  std::ofstream(other, std::ios::binary) << std::string("\x89HDF\r\n\x1a\n", 8) << std::string(512, '\0');
  try {
    load_vtk_data({other});
    FAIL() << "read an HDF5 file without /VTKHDF";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find(other + ": not a VTK HDF file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hsb
