// Files whose headers declare more than they hold, or more than memory
// holds: each one DataError naming the file, never values read as zeros
// past the end of the file, nor a bare std::bad_alloc. (NIfTI's and NRRD's
// own are beside their readers' tests.)

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "field/reading/data_error.h"
#include "field/reading/netcdf_extent.h"
#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

// MOOSE's Exodus II results, three time steps, netCDF classic (64-bit
// offsets), copied to `name` to be broken.
fs::path moose_copy(const std::string& name) {
  const fs::path copy = test_temp_dir("declared_sizes") / name;
  fs::copy_file(fs::path(HSB_SOURCE_DIR) / "scenes/data/formats/moose_style.e", copy,
                fs::copy_options::overwrite_existing);
  return copy;
}

// The message of the DataError that reading `path` throws.
std::string error_of(const fs::path& path) {
  try {
    load_vtk_data({path.string()});
  } catch (const DataError& e) {
    return e.what();
  }
  return "no error";
}

// What the tools' own files declare is what they hold, to the byte where
// the netCDF library pads the file to its declared size (MOOSE's and
// Sierra's, netCDF classic with 64-bit offsets); meshio's netCDF-4 (HDF5
// inside) is no classic file.
TEST(DeclaredSizes, TheToolsExodusFilesHoldWhatTheirHeadersDeclare) {
  for (const char* name : {"scenes/data/formats/moose_style.e", "scenes/data/formats/sierra_style.exo"}) {
    const fs::path path = fs::path(HSB_SOURCE_DIR) / name;
    const std::optional<NetcdfExtent> extent = netcdf_classic_extent(path.string());
    ASSERT_TRUE(extent) << name;
    EXPECT_EQ(extent->bytes, fs::file_size(path)) << name;
    EXPECT_EQ(extent->records_held, extent->records) << name;
  }
  EXPECT_EQ(netcdf_classic_extent(moose_copy("three.e").string())->records, 3u);
  const fs::path netcdf4 = fs::path(HSB_SOURCE_DIR) / "tests/field/data/meshio_nodal_variables.e";
  EXPECT_FALSE(netcdf_classic_extent(netcdf4.string()));
}

// The netCDF library reads past a file's end as zeros, without an error:
// a file cut short read as a field of zeros at its last step.
TEST(DeclaredSizes, AnExodusFileCutShortIsRefused) {
  const fs::path whole = moose_copy("whole.e");
  EXPECT_EQ(error_of(whole), "no error");
  const fs::path cut = moose_copy("cut.e");
  fs::resize_file(cut, fs::file_size(whole) - 100);  // into the last step's values
  std::string e = error_of(cut);
  EXPECT_EQ(e.rfind(cut.string() + ": its header declares 3 time steps, but its ", 0), 0u) << e;
  EXPECT_NE(e.find("the file is cut short"), std::string::npos) << e;
  fs::resize_file(cut, 5000);  // into the mesh
  e = error_of(cut);
  EXPECT_EQ(e.rfind(cut.string() + ": ", 0), 0u) << e;
  EXPECT_NE(e.find("cut short"), std::string::npos) << e;
}

// A header that claims 1000 time steps where the file holds 3: the steps
// past the end had times and values of zero.
TEST(DeclaredSizes, AnExodusFileClaimingMoreTimeStepsThanItHoldsIsRefused) {
  const fs::path claiming = moose_copy("claiming.e");
  {
    // netCDF classic's record count (the time steps): bytes 4–7, big-endian.
    std::fstream file(claiming, std::ios::in | std::ios::out | std::ios::binary);
    const char thousand[4] = {0, 0, 0x03, char(0xE8)};
    file.seekp(4);
    file.write(thousand, 4);
  }
  const std::string e = error_of(claiming);
  EXPECT_EQ(e.rfind(claiming.string() + ": its header declares 1000 time steps, but its ", 0), 0u) << e;
  EXPECT_NE(e.find(" hold 3 of them whole"), std::string::npos) << e;
  EXPECT_THROW(series_times(claiming.string()), DataError);
}

// VTK's XML reader meets a count larger than memory with a bare
// std::bad_alloc: said as what it is, naming the file.
TEST(DeclaredSizes, ACountLargerThanMemoryIsSaidSo) {
  const fs::path path = test_temp_dir("declared_sizes") / "huge.vtu";
  std::ofstream(path) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
                         "<UnstructuredGrid><Piece NumberOfPoints=\"9000000000000000\" NumberOfCells=\"1\">\n"
                         "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
                         "0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>\n"
                         "<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>"
                         "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4</DataArray>"
                         "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray></Cells>\n"
                         "</Piece></UnstructuredGrid></VTKFile>\n";
  const std::string e = error_of(path);
  EXPECT_EQ(e, path.string() + ": cannot read it as a VTK data set: it declares more than memory holds (VTK could "
                               "not allocate what its sizes ask for)");
}

}  // namespace
}  // namespace hsb
