// Data files a user may give by mistake or that broke on the way: each
// gets one DataError naming the file and what is wrong, never a crash.
// The files are legacy ASCII, written here line by line, so that each
// test breaks exactly one thing.

#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <random>
#include <sstream>

#include "field/reading/data_error.h"
#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"
#include "tests/without_waiting.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

// A 2×2×2 block of hexahedra (27 points, 8 cells) with point tensors, as
// legacy ASCII; `edit` may change the lines before they are joined.
struct LegacyGrid {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<long, 8>> cells;
  std::vector<std::array<double, 9>> tensors;
  long declared_cells = -1;  // the CELLS count written, when not the real one
  int cell_type = 12;        // VTK_HEXAHEDRON

  LegacyGrid() {
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
          points.push_back({0.5 * i, 0.5 * j, 0.5 * k});
          tensors.push_back({1.0 + i, 0.1, 0, 0.1, 0.5 + k, 0, 0, 0, -1});
        }
    const auto n = [](int i, int j, int k) { return long(k * 9 + j * 3 + i); };
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
          cells.push_back({n(i, j, k), n(i + 1, j, k), n(i + 1, j + 1, k), n(i, j + 1, k), n(i, j, k + 1),
                           n(i + 1, j, k + 1), n(i + 1, j + 1, k + 1), n(i, j + 1, k + 1)});
  }

  std::string text() const {
    std::ostringstream out;
    out.precision(17);
    out << "# vtk DataFile Version 4.2\nbad data\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << points.size() << " double\n";
    for (const auto& p : points) out << p[0] << " " << p[1] << " " << p[2] << "\n";
    out << "CELLS " << (declared_cells >= 0 ? declared_cells : long(cells.size())) << " " << cells.size() * 9 << "\n";
    for (const auto& c : cells) {
      out << 8;
      for (long id : c) out << " " << id;
      out << "\n";
    }
    out << "CELL_TYPES " << cells.size() << "\n";
    for (std::size_t i = 0; i < cells.size(); ++i) out << cell_type << "\n";
    out << "POINT_DATA " << points.size() << "\nTENSORS stress double\n";
    for (const auto& t : tensors)
      out << t[0] << " " << t[1] << " " << t[2] << "\n" << t[3] << " " << t[4] << " " << t[5] << "\n"
          << t[6] << " " << t[7] << " " << t[8] << "\n";
    return out.str();
  }
};

// One tetrahedron as VTK XML, ASCII, with `points` as its coordinates and
// a 6-component array "stress", marked as the active tensors or not.
std::string tetrahedron_vtu(const std::string& points, bool active) {
  return std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
                     "<UnstructuredGrid>\n<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<PointData") +
         (active ? " Tensors=\"stress\"" : "") +
         "><DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"6\" format=\"ascii\">"
         "1 2 3 0 0 0 1 2 3 0 0 0 1 2 3 0 0 0 1 2 3 0 0 0</DataArray></PointData>\n"
         "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">" + points +
         "</DataArray></Points>\n"
         "<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>"
         "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4</DataArray>"
         "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray></Cells>\n"
         "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

class BadData : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path dir = test_temp_dir("bad_data");
    fs::create_directories(dir);
    const fs::path path = dir / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  // The message of the DataError that loading `path` throws.
  static std::string error_of(const fs::path& path) {
    try {
      VtkFileSpec spec;
      spec.path = path.string();
      load_vtk_data(spec);
    } catch (const DataError& e) {
      return e.what();
    }
    return "no error";
  }
};

TEST_F(BadData, TheWellFormedGridReads) {
  VtkFileSpec spec;
  spec.path = write("good.vtk", LegacyGrid().text()).string();
  EXPECT_NO_THROW(load_vtk_data(spec));
}

TEST_F(BadData, ACellCountLargerThanTheCells) {
  for (long declared : {1000L, 2000000000L}) {
    LegacyGrid grid;
    grid.declared_cells = declared;
    const fs::path path = write("cells_" + std::to_string(declared) + ".vtk", grid.text());
    EXPECT_EQ(error_of(path).rfind(path.string() + ": cannot read it as a VTK data set: Error reading", 0), 0u)
        << error_of(path);
  }
}

TEST_F(BadData, ACellNamingAPointThatDoesNotExist) {
  LegacyGrid grid;
  grid.cells[3][2] = 99999;
  const fs::path path = write("bad_point.vtk", grid.text());
  EXPECT_EQ(error_of(path), path.string() + ": a cell names point 99999, but the points are 0 to 26");
  grid.cells[3][2] = -4;
  const fs::path negative = write("negative_point.vtk", grid.text());
  EXPECT_NE(error_of(negative).find("names point -4"), std::string::npos) << error_of(negative);
}

TEST_F(BadData, CellsWithTheWrongNumberOfPointsForTheirType) {
  // Found by the data fuzzer: VTK's filters read such cells past their end.
  LegacyGrid wedge;
  wedge.cell_type = 32;  // a biquadratic-quadratic wedge has 18 points, not 8
  const fs::path path = write("wrong_size.vtk", wedge.text());
  EXPECT_EQ(error_of(path), path.string() + ": cell 0 is a vtkBiQuadraticQuadraticWedge with 8 points; it needs 18");
  LegacyGrid unknown;
  unknown.cell_type = 200;
  const fs::path bad = write("unknown_type.vtk", unknown.text());
  EXPECT_NE(error_of(bad).find("cell 0 has type 200, which is no VTK cell type"), std::string::npos) << error_of(bad);
  LegacyGrid lagrange;
  lagrange.cell_type = 72;  // VTK_LAGRANGE_HEXAHEDRON
  const fs::path higher = write("lagrange.vtk", lagrange.text());
  EXPECT_NE(error_of(higher).find("only linear and quadratic cells are supported"), std::string::npos) << error_of(higher);
}

// Points with tensors and no cells are a point cloud, not an error: its
// values are drawn where they stand.
TEST_F(BadData, NoCellsAtAllIsAPointCloud) {
  LegacyGrid grid;
  grid.cells.clear();
  const fs::path path = write("no_cells.vtk", grid.text());
  const VtkData data = load_vtk_data({path.string()});
  EXPECT_NE(data.no_volume.find("it has points but no cells"), std::string::npos) << data.no_volume;
  EXPECT_FALSE(data.sites.positions.empty());
  EXPECT_EQ(data.sites.positions.size(), data.sites.tensors.size());
}

TEST_F(BadData, OnlyFlatCells) {
  LegacyGrid grid;
  for (auto& p : grid.points) p[2] = 0.0;  // every hexahedron squashed flat
  const fs::path path = write("flat.vtk", grid.text());
  EXPECT_EQ(error_of(path), path.string() + ": none of its 8 cells has any volume (8 are 3D cells, all flat): "
                                            "tensors are sampled inside 3D cells");
  LegacyGrid quads;
  quads.cell_type = 11;  // VTK_VOXEL is 3D too; a pixel is not
  for (auto& c : quads.cells) c = {c[0], c[1], c[3], c[2], c[4], c[5], c[7], c[6]};
  EXPECT_EQ(error_of(write("voxels.vtk", quads.text())), "no error");  // voxels with volume are fine
}

// A slender body is not flat: a rod 10,000 long of unit cubes, each cell
// with volume for its size, however small beside the rod's length (it
// was refused as "all flat" when volume was measured against the body).
TEST_F(BadData, ASlenderBodyOfGoodCellsIsNoFlatMesh) {
  LegacyGrid rod;
  constexpr int n = 10000;
  rod.points.clear(), rod.cells.clear(), rod.tensors.clear();
  for (int i = 0; i <= n; ++i)
    for (int corner = 0; corner < 4; ++corner) {
      rod.points.push_back({double(i), double(corner == 1 || corner == 2), double(corner >= 2)});
      rod.tensors.push_back({1.0, 0.1, 0, 0.1, 0.5, 0, 0, 0, -1});
    }
  for (long i = 0; i < n; ++i) {
    const long a = 4 * i, b = 4 * (i + 1);  // corners (y, z): 0 (0,0), 1 (1,0), 2 (1,1), 3 (0,1)
    rod.cells.push_back({a, b, b + 1, a + 1, a + 3, b + 3, b + 2, a + 2});
  }
  EXPECT_EQ(error_of(write("rod.vtk", rod.text())), "no error");
}

TEST_F(BadData, NonFinitePointCoordinates) {
  // Legacy ASCII cannot even spell NaN ...
  LegacyGrid grid;
  grid.points[5][1] = std::nan("");
  const fs::path legacy = write("nan_point.vtk", grid.text());
  EXPECT_EQ(error_of(legacy), legacy.string() + ": cannot read it as a VTK data set: Unrecognized keyword: nan");
  // ... XML can: one tetrahedron with a NaN corner.
  const fs::path path = write("nan_point.vtu", tetrahedron_vtu("0 0 0 1 0 0 0 nan 0 0 0 1", true));
  EXPECT_EQ(error_of(path), path.string() + ": point 2 has a non-finite coordinate (0, nan, 0)");
}

// A 3 × 3 × 3 image of one tensor with the given spacing.
std::string image_vti(const std::string& spacing) {
  std::string tensors;
  for (int i = 0; i < 27; ++i) tensors += "1 2 3 0 0 0 ";
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\">\n"
         "<ImageData WholeExtent=\"0 2 0 2 0 2\" Origin=\"0 0 0\" Spacing=\"" + spacing + "\">\n"
         "<Piece Extent=\"0 2 0 2 0 2\">\n<PointData Tensors=\"stress\">"
         "<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"6\" format=\"ascii\">" + tensors +
         "</DataArray></PointData>\n<CellData/>\n</Piece>\n</ImageData>\n</VTKFile>\n";
}

TEST_F(BadData, AnImageWhosePointsOverflowSaysWhichIsTheFirst) {
  // Its points are found from its corners (an image's coordinates are
  // linear in the index); one beyond a double's range is still named.
  EXPECT_EQ(error_of(write("fine.vti", image_vti("1 2 1"))), "no error");
  const fs::path path = write("overflow.vti", image_vti("1 1e308 1"));
  EXPECT_EQ(error_of(path), path.string() + ": point 6 has a non-finite coordinate (0, inf, 0)");
}

TEST_F(BadData, TheOnlySixComponentArrayIsTheTensorsWithoutBeingActive) {
  const fs::path path = write("inactive.vtu", tetrahedron_vtu("0 0 0 1 0 0 0 1 0 0 0 1", false));
  EXPECT_EQ(error_of(path), "no error");
  VtkFileSpec spec;
  spec.path = path.string();
  EXPECT_NE(describe_vtk_file(spec).find("tensors   \"stress\" (6 components, point data)"), std::string::npos)
      << describe_vtk_file(spec);
}

TEST_F(BadData, TruncatedFiles) {
  const std::string text = LegacyGrid().text();
  for (double fraction : {0.2, 0.5, 0.9, 0.99}) {
    const fs::path path = write("truncated.vtk", text.substr(0, std::size_t(fraction * double(text.size()))));
    const std::string e = error_of(path);
    EXPECT_EQ(e.rfind(path.string() + ": ", 0), 0u) << fraction << ": " << e;
    EXPECT_NE(e, "no error") << fraction;
  }
}

TEST_F(BadData, RandomBytesWithAVtkExtension) {
  std::mt19937 rng(3);
  for (const char* ext : {".vtk", ".vtu", ".vti", ".vts", ".vtr"}) {
    std::string bytes(3000, '\0');
    for (char& c : bytes) c = char(rng());
    const fs::path path = write(std::string("random") + ext, bytes);
    const std::string e = error_of(path);
    EXPECT_EQ(e.rfind(path.string() + ": not a ", 0), 0u) << e;
  }
  // Well-formed XML that is not a VTK file.
  const fs::path xml = write("other.vtu", "<?xml version=\"1.0\"?>\n<html><body>hello</body></html>\n");
  EXPECT_EQ(error_of(xml).rfind(xml.string() + ": cannot read it as a VTK data set: ", 0), 0u) << error_of(xml);
}

TEST_F(BadData, ADirectoryNamedLikeADataFile) {
  const fs::path dir = test_temp_dir("bad_data") / "folder.vtu";
  fs::create_directories(dir);
  EXPECT_EQ(error_of(dir), dir.string() + ": a directory, not a file");
}

TEST_F(BadData, AFileItMayNotReadIsSaidSo) {
  if (geteuid() == 0) GTEST_SKIP() << "root reads any file";
  const fs::path locked = write("locked.vtu", "<?xml version=\"1.0\"?>\n");
  fs::permissions(locked, fs::perms::none);
  EXPECT_EQ(error_of(locked), locked.string() + ": cannot be read: Permission denied");
  fs::permissions(locked, fs::perms::owner_all);
}

// What loading `path` says (BadData::error_of), which must not wait on the
// FIFO `fifo`.
std::string error_without_waiting(const fs::path& path, const fs::path& fifo) {
  return without_waiting(fifo, [&] {
    try {
      load_vtk_data({path.string()});
    } catch (const DataError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  });
}

// A FIFO where a data file names its data (a detached NRRD header's "data
// file:", a parallel file's piece) would keep its reader waiting for a
// writer for ever, and a render, an info or a whole batch with it: one
// DataError naming it instead, at once. A device is refused alike.
TEST_F(BadData, AFifoNamedAsTheDataIsRefusedAtOnce) {
  const fs::path dir = test_temp_dir("bad_data");
  const fs::path fifo = dir / "fifo.raw";
  fs::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::ifstream shipped(std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/teem_helix_detached.nhdr");
  std::string header;
  for (std::string line; std::getline(shipped, line);)
    header += (line.rfind("data file:", 0) == 0 ? "data file: fifo.raw" : line) + "\n";
  const fs::path nhdr = write("fifo.nhdr", header);
  EXPECT_EQ(error_without_waiting(nhdr, fifo),
            nhdr.string() + ": names " + fifo.string() + ": not a regular file (a FIFO, socket or device)");
  const std::string zero = header.substr(0, header.find("data file:")) + "data file: /dev/zero\n";
  const fs::path devices = write("zero.nhdr", zero);
  EXPECT_EQ(error_of(devices), devices.string() + ": names /dev/zero: not a regular file (a FIFO, socket or device)");

  const fs::path piece = dir / "fifo.vtu";
  fs::remove(piece);
  ASSERT_EQ(mkfifo(piece.c_str(), 0600), 0);
  write("good.vtu", tetrahedron_vtu("0 0 0 1 0 0 0 1 0 0 0 1", true));
  const fs::path pvtu = write("fifo.pvtu",
                              "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\">\n"
                              "<PUnstructuredGrid GhostLevel=\"0\">\n<PPointData Tensors=\"stress\">"
                              "<PDataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"6\"/></PPointData>\n"
                              "<PPoints><PDataArray type=\"Float64\" NumberOfComponents=\"3\"/></PPoints>\n"
                              "<Piece Source=\"good.vtu\"/>\n<Piece Source=\"fifo.vtu\"/>\n"
                              "</PUnstructuredGrid>\n</VTKFile>\n");
  EXPECT_EQ(error_without_waiting(pvtu, piece),
            pvtu.string() + ": names " + piece.string() + ": not a regular file (a FIFO, socket or device)");
}

// The reading child hands its result and its messages back through
// scratch files. They were at names anyone could foresee in the shared
// temporary folder ($TMPDIR/.hsb-WHAT-PID.partial-HOST-PID.EXT), and the
// parent read back whatever was there: another user's planted message was
// this file's error (terminal escape codes and all), a link made the child
// write through it, and what the child could not overwrite was read as the
// user's data. Now they are in a folder of the process's own, and nothing
// planted at the old names is read or written.
TEST_F(BadData, WhatIsPlantedAtTheOldScratchNamesIsNeverReadNorWrittenThrough) {
  char name[256] = {};
  std::string host = gethostname(name, sizeof name - 1) == 0 && name[0] ? name : "host";
  for (char& c : host)
    if (c == '/' || c == '.') c = '_';
  const std::string pid = std::to_string(getpid());
  const fs::path temp = fs::temp_directory_path();
  const auto old_name = [&](const std::string& what, const std::string& extension) {
    return temp / (".hsb-" + what + "-" + pid + ".partial-" + host + "-" + pid + extension);
  };
  const fs::path failure = old_name("failure", ".txt"), read = old_name("read", ".vtkxml");
  std::ofstream(failure) << "planted: \x1b[2J\x1b[31mthis file is corrupt";
  const fs::path victim = test_temp_dir("bad_data") / "victim.txt";
  std::ofstream(victim) << "the victim's";
  fs::remove_all(read);
  fs::create_symlink(victim, read);
  const fs::path planted_folder = old_name("read", ".folder");
  fs::create_directories(planted_folder / "inside");

  VtkFileSpec spec;
  spec.path = write("good_planted.vtk", LegacyGrid().text()).string();
  spec.sites = true;
  std::string error;
  try {
    const VtkData data = load_vtk_data(spec);
    ASSERT_FALSE(data.sites.positions.empty());
    for (std::size_t i = 0; i < data.sites.positions.size(); ++i) EXPECT_LE(data.sites.positions[i].maxCoeff(), 1.0);
  } catch (const DataError& e) {
    error = e.what();
  }
  EXPECT_EQ(error, "");
  std::ifstream in(victim);
  const std::string victims = std::string(std::istreambuf_iterator<char>(in), {});
  EXPECT_TRUE(victims == "the victim's") << "written through the link: " << victims.size() << " bytes";
  // What the child could not overwrite (here a folder) was read back.
  fs::remove(read);
  fs::rename(planted_folder, read);
  try {
    load_vtk_data(spec);
  } catch (const DataError& e) {
    ADD_FAILURE() << e.what();
  }
  fs::remove(failure);
  fs::remove_all(read);
}

TEST_F(BadData, WrongComponentCount) {
  std::string text = LegacyGrid().text();
  text = text.substr(0, text.find("TENSORS"));
  text += "VECTORS velocity double\n";
  for (int i = 0; i < 27; ++i) text += "1 0 0\n";
  const fs::path path = write("vectors.vtk", text);
  EXPECT_EQ(error_of(path), "no error");  // read as a flow
  VtkFileSpec tensors;
  tensors.path = path.string();
  tensors.kind = FieldKind::tensor;
  try {
    load_vtk_data(tensors);
    FAIL() << "no error";
  } catch (const DataError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("no active tensors and no single array of 6 or 9 components"), std::string::npos) << m;
    EXPECT_NE(m.find("velocity (3 components)"), std::string::npos) << m;
  }
  // Two components are neither.
  std::string two = LegacyGrid().text();
  two = two.substr(0, two.find("TENSORS")) + "FIELD extra 1\nflat 2 27 double\n";
  for (int i = 0; i < 27; ++i) two += "1 0\n";
  VtkFileSpec named;
  named.path = write("two.vtk", two).string();
  named.array = "flat";
  try {
    load_vtk_data(named);
    FAIL() << "no error";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("has 2 components; a tensor needs 9, or 6 (XX, YY, ZZ, XY, YZ, XZ); a vector 3"),
              std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hsb
