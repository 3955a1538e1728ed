// XDMF with HDF5 heavy data as FEniCS (dolfin 2019, dolfinx 0.5) and meshio 5 write it
// (scenes/data/generators/formats/README_xdmf_hdf.md): the mesh, cells
// wound as VTK winds them, both time steps of dolfin's series (the second
// takes the mesh by xi:include), a cell-centred tensor, meshio's Tensor6
// order; inline XML data and Mixed cells as XDMF 2 writers leave them; and
// one DataError naming the file for each broken file.

#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "field/reading/block_merging.h"
#include "field/reading/component_arrays.h"
#include "field/reading/data_error.h"
#include "field/reading/format_reader.h"
#include "field/reading/vtk_data.h"
#include "field/reading/vtk_session.h"
#include "field/tensor/eigensystem.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

const std::string formats = std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/";
const std::string shaft = formats + "fenics_shaft.xdmf";
const std::string shaft_dg0 = formats + "fenics_shaft_dg0.xdmf";
const std::string beam = formats + "meshio_hex_beam.xdmf";
const std::string dolfinx_plate = formats + "dolfinx_plate.xdmf";

// The grid the reader makes of `path`, before hsb's checks.
vtkSmartPointer<vtkUnstructuredGrid> read_grid(const std::string& path, int step = -1) {
  const VtkSession vtk;
  ReadRequest request;
  request.step = step;
  return vtkUnstructuredGrid::SafeDownCast(xdmf_reader.read(path, request, vtk));
}

// The determinant of VTK's own parametric map at each cell's centre
// (its shape functions' derivatives): positive for a cell wound as VTK
// winds it, whatever the reader did to get there.
std::vector<double> centre_jacobians(vtkUnstructuredGrid* grid) {
  std::vector<double> jacobians;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    vtkCell* cell = grid->GetCell(c);
    double centre[3], derivs[3 * 27] = {};
    cell->GetParametricCenter(centre);
    cell->InterpolateDerivs(centre, derivs);
    Mat3 j = Mat3::Zero();
    const vtkIdType n = cell->GetNumberOfPoints();
    for (vtkIdType i = 0; i < n; ++i) {
      double x[3];
      cell->GetPoints()->GetPoint(i, x);
      for (int a = 0; a < 3; ++a)
        for (int r = 0; r < 3; ++r) j(a, r) += x[a] * derivs[r * n + i];
    }
    jacobians.push_back(j.determinant());
  }
  return jacobians;
}

Mat3 tensor_at(vtkDataArray* nine, vtkIdType i) {
  Mat3 t;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) t(r, c) = nine->GetComponent(i, 3 * r + c);
  return t;
}

std::string copied(const std::string& from, const fs::path& to) {
  fs::copy_file(from, to, fs::copy_options::overwrite_existing);
  return to.string();
}

// The DataError reading `path` gives (failing the test if none).
std::string read_error(const std::string& path) {
  try {
    load_vtk_data({path});
  } catch (const DataError& e) {
    return e.what();
  }
  ADD_FAILURE() << "read " << path;
  return "";
}

TEST(XdmfReading, DolfinsShaftReadsWithItsTetrahedraWoundAsVtks) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(shaft);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->GetNumberOfPoints(), 2267);
  ASSERT_EQ(grid->GetNumberOfCells(), 8998);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) ASSERT_EQ(grid->GetCellType(c), VTK_TETRA) << c;
  // dolfin sorts each tetrahedron's vertices: about half come wound the other way.
  const std::vector<double> jacobians = centre_jacobians(grid);
  for (std::size_t c = 0; c < jacobians.size(); ++c) ASSERT_GT(jacobians[c], 0.0) << "cell " << c;
  vtkDataArray* stress = grid->GetPointData()->GetArray("stress");
  vtkDataArray* displacement = grid->GetPointData()->GetArray("displacement");
  ASSERT_TRUE(stress && displacement);
  EXPECT_EQ(stress->GetNumberOfComponents(), 9);
  EXPECT_EQ(displacement->GetNumberOfComponents(), 3);
  // The stress is dolfin's float64, read as it is stored (XDMF's default
  // Precision would make it float32): σzz at node 616.
  EXPECT_EQ(stress->GetComponent(616, 8), 223.20605001521722);
}

TEST(XdmfReading, TheShaftsPeakIsAtTheGrooveRoot) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(shaft, 0);
  ASSERT_TRUE(grid);
  vtkDataArray* stress = grid->GetPointData()->GetArray("stress");
  ASSERT_TRUE(stress);
  double peak = -1e300;
  vtkIdType at = -1;
  for (vtkIdType i = 0; i < stress->GetNumberOfTuples(); ++i) {
    const double major = eigenvalues(Sym3::symmetric_part(tensor_at(stress, i))).x();
    if (major > peak) peak = major, at = i;
  }
  EXPECT_NEAR(peak, 224.0, 0.05);
  double x[3];
  grid->GetPoint(at, x);
  EXPECT_NEAR(x[0], 6.95, 0.005);
  EXPECT_NEAR(x[1], 3.97, 0.005);
  EXPECT_NEAR(x[2], 0.135, 0.005);

  // The same through hsb's reading, sampled at the peak, just inside the groove root.
  const VtkData data = load_vtk_data({shaft});
  ASSERT_TRUE(data.field);
  const std::optional<Sym3> s = data.field->sample(Vec3(6.95, 3.97, 0.135) * 0.999);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->zz, 223.0, 2.0);
}

TEST(XdmfReading, TheSecondStepTakesTheMeshByXInclude) {
  EXPECT_EQ(xdmf_reader.times(shaft), (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(series_times(shaft), (std::vector<double>{1.0, 2.0}));
  const vtkSmartPointer<vtkUnstructuredGrid> first = read_grid(shaft, 0), second = read_grid(shaft, 1);
  ASSERT_TRUE(first && second);
  ASSERT_EQ(second->GetNumberOfCells(), 8998);
  vtkDataArray* s0 = first->GetPointData()->GetArray("stress");
  vtkDataArray* s1 = second->GetPointData()->GetArray("stress");
  ASSERT_TRUE(s0 && s1);
  for (vtkIdType node : {0, 616, 2266})
    for (int c = 0; c < 9; ++c) EXPECT_EQ(s1->GetComponent(node, c), 2.0 * s0->GetComponent(node, c));
  VtkFileSpec second_step{shaft};
  second_step.step = 1;
  const VtkData doubled = load_vtk_data(second_step);
  ASSERT_TRUE(doubled.field);
  const std::optional<Sym3> s = doubled.field->sample(Vec3(6.95, 3.97, 0.135) * 0.999);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->zz, 446.0, 4.0);
  EXPECT_THROW(read_grid(shaft, 2), DataError);
}

TEST(XdmfReading, TheHeavyDataFileIsAPartOfTheData) {
  const std::vector<std::string> files = data_files_read(shaft);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(fs::path(files[1]).filename(), "fenics_shaft.h5");
}

TEST(XdmfReading, DolfinsCellTensorsAreCellData) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(shaft_dg0);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->GetNumberOfCells(), 8998);
  EXPECT_FALSE(grid->GetPointData()->GetArray("stress"));
  vtkDataArray* stress = grid->GetCellData()->GetArray("stress");
  ASSERT_TRUE(stress);
  EXPECT_EQ(stress->GetNumberOfComponents(), 9);
  EXPECT_EQ(stress->GetNumberOfTuples(), 8998);
  EXPECT_NEAR(stress->GetRange(8)[1], 191.3, 0.05);   // σzz in the root cells
  EXPECT_TRUE(xdmf_reader.times(shaft_dg0).empty());  // one step
  const VtkData data = load_vtk_data({shaft_dg0});
  ASSERT_TRUE(data.field);
  EXPECT_TRUE(data.field->sample(Vec3(0.0, 0.0, 20.0)));
}

TEST(XdmfReading, MeshiosTensor6IsTurnedIntoVtksOrder) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(beam);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->GetNumberOfPoints(), 1519);
  ASSERT_EQ(grid->GetNumberOfCells(), 1080);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) ASSERT_EQ(grid->GetCellType(c), VTK_HEXAHEDRON) << c;
  const std::vector<double> jacobians = centre_jacobians(grid);
  for (std::size_t c = 0; c < jacobians.size(); ++c) ASSERT_GT(jacobians[c], 0.0) << "cell " << c;
  vtkDataArray* stress = grid->GetPointData()->GetArray("stress");
  ASSERT_TRUE(stress);
  ASSERT_EQ(stress->GetNumberOfComponents(), 6);
  // The root's node on the neutral plane: pure shear σxz = −1.5. Read in
  // VTK's order, the file's XZ would land in σzz.
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double x[3];
    grid->GetPoint(i, x);
    if (x[0] != 0.0 || x[1] != 0.0 || x[2] != 0.0) continue;
    EXPECT_DOUBLE_EQ(stress->GetComponent(i, 5), -1.5);  // XZ
    EXPECT_DOUBLE_EQ(stress->GetComponent(i, 2), 0.0);   // ZZ
    EXPECT_DOUBLE_EQ(stress->GetComponent(i, 0), 0.0);   // XX
  }
  EXPECT_NE(recorded_component_order(grid, "stress").find("Tensor6"), std::string::npos);
  vtkDataArray* von_mises = grid->GetCellData()->GetArray("von_mises");
  ASSERT_TRUE(von_mises);
  EXPECT_EQ(von_mises->GetNumberOfTuples(), 1080);
  EXPECT_TRUE(xdmf_reader.times(beam).empty());

  const VtkData data = load_vtk_data({beam});
  ASSERT_TRUE(data.field);
  const std::optional<Sym3> top = data.field->sample(Vec3(0.05, 0.0, 0.49));
  ASSERT_TRUE(top);
  EXPECT_NEAR(top->xx, 12 * (10 - 0.05) * 0.49, 0.5);
}

// A hexahedron, a wedge on it and a pyramid under it in one Mixed
// topology, every value in the XML as XDMF 2 writers leave small data; the
// pyramid's nodes as a writer that winds it the other way gives them.
TEST(XdmfReading, InlineMixedCellsReadWithoutHeavyData) {
  const std::string path = (test_temp_dir("xdmf") / "mixed.xmf").string();
  std::ofstream(path) << R"(<?xml version="1.0" ?>
<Xdmf Version="2.0">
 <Domain>
  <DataItem Name="corners" Format="XML" Dimensions="12 3">
   0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1  0 0 2  1 0 2  0 1 2  0.5 0.5 -1
  </DataItem>
  <Grid Name="block" GridType="Uniform">
   <Topology TopologyType="Mixed" NumberOfElements="3">
    <DataItem Format="XML" DataType="Int" Dimensions="22">9 0 1 2 3 4 5 6 7  8 4 5 7 8 9 10  7 0 1 2 3 11</DataItem>
   </Topology>
   <Geometry GeometryType="XYZ">
    <DataItem Reference="XML">/Xdmf/Domain/DataItem[@Name="corners"]</DataItem>
   </Geometry>
   <Attribute Name="stress" AttributeType="Tensor6" Center="Cell">
    <DataItem Format="XML" Dimensions="3 6">1 2 3 4 5 6  10 20 30 40 50 60  0 0 0 0 0 0</DataItem>
   </Attribute>
   <Attribute Name="temperature" Center="Node">
    <DataItem Format="XML" Dimensions="12">0 1 2 3 4 5 6 7 8 9 10 11</DataItem>
   </Attribute>
  </Grid>
 </Domain>
</Xdmf>
)";
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(path);
  ASSERT_TRUE(grid);
  ASSERT_EQ(grid->GetNumberOfCells(), 3);
  EXPECT_EQ(grid->GetCellType(0), VTK_HEXAHEDRON);
  EXPECT_EQ(grid->GetCellType(1), VTK_WEDGE);
  EXPECT_EQ(grid->GetCellType(2), VTK_PYRAMID);
  for (double j : centre_jacobians(grid)) EXPECT_GT(j, 0.0);
  const auto nodes = [&](vtkIdType c) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    grid->GetCellPoints(c, n, ids);
    return std::vector<vtkIdType>(ids, ids + n);
  };
  EXPECT_EQ(nodes(1), (std::vector<vtkIdType>{4, 5, 7, 8, 9, 10}));  // as written
  EXPECT_EQ(nodes(2), (std::vector<vtkIdType>{0, 3, 2, 1, 11}));     // turned round
  vtkDataArray* stress = grid->GetCellData()->GetArray("stress");
  ASSERT_TRUE(stress);
  const double vtk_order[6] = {10, 40, 60, 20, 50, 30};  // XX YY ZZ XY YZ XZ
  for (int c = 0; c < 6; ++c) EXPECT_EQ(stress->GetComponent(1, c), vtk_order[c]) << c;
  ASSERT_TRUE(grid->GetPointData()->GetArray("temperature"));
  EXPECT_EQ(grid->GetPointData()->GetArray("temperature")->GetComponent(9, 0), 9.0);
}

// A quadratic tetrahedron and a quadratic wedge, each written mirrored
// (numbered from 1, as BaseOffset allows): both come out in VTK's order,
// their mid-edge nodes moved with their corners.
TEST(XdmfReading, MirroredQuadraticCellsAreTurnedRound) {
  const std::string path = (test_temp_dir("xdmf") / "quadratic.xmf").string();
  std::ofstream(path) << R"(<Xdmf Version="3.0"><Domain><Grid Name="quadratic">
<Topology TopologyType="Mixed" NumberOfElements="2" BaseOffset="1"><DataItem Dimensions="27">
 38  1 3 2 4 7 6 5 8 10 9
 40  14 15 16 11 12 13 20 21 22 17 18 19 23 24 25</DataItem></Topology>
<Geometry GeometryType="XYZ"><DataItem Dimensions="25 3">
 0 0 0  1 0 0  0 1 0  0 0 1  0.5 0 0  0.5 0.5 0  0 0.5 0  0 0 0.5  0.5 0 0.5  0 0.5 0.5
 2 0 0  3 0 0  2 1 0  2 0 1  3 0 1  2 1 1
 2.5 0 0  2.5 0.5 0  2 0.5 0  2.5 0 1  2.5 0.5 1  2 0.5 1  2 0 0.5  3 0 0.5  2 1 0.5</DataItem></Geometry>
</Grid></Domain></Xdmf>)";
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(path);
  ASSERT_TRUE(grid);
  ASSERT_EQ(grid->GetNumberOfCells(), 2);
  EXPECT_EQ(grid->GetCellType(0), VTK_QUADRATIC_TETRA);
  EXPECT_EQ(grid->GetCellType(1), VTK_QUADRATIC_WEDGE);
  for (double j : centre_jacobians(grid)) EXPECT_GT(j, 0.0);
  for (vtkIdType c = 0; c < 2; ++c) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    grid->GetCellPoints(c, n, ids);
    for (vtkIdType i = 0; i < n; ++i) EXPECT_EQ(ids[i], (c == 0 ? 0 : 10) + i) << "cell " << c;
  }
}

// Two pieces of a parallel run in a spatial collection: one grid, each
// piece a block.
TEST(XdmfReading, ASpatialCollectionsPiecesAreMerged) {
  const std::string path = (test_temp_dir("xdmf") / "pieces.xdmf").string();
  const auto piece = [](const char* name, double x0) {
    const std::string x = std::to_string(x0), x1 = std::to_string(x0 + 1);
    return std::string("<Grid Name=\"") + name + R"("><Topology TopologyType="Tetrahedron" NumberOfElements="1">)" +
           R"(<DataItem Dimensions="1 4">0 1 2 3</DataItem></Topology><Geometry GeometryType="X_Y_Z">)" +
           "<DataItem Dimensions=\"4\">" + x + " " + x1 + " " + x + " " + x + "</DataItem>" +
           R"(<DataItem Dimensions="4">0 0 1 0</DataItem><DataItem Dimensions="4">0 0 0 1</DataItem></Geometry>)" +
           R"(<Attribute Name="stress" AttributeType="Tensor" Center="Cell"><DataItem Dimensions="1 9">)" +
           "1 0 0 0 2 0 0 0 3</DataItem></Attribute></Grid>";
  };
  std::ofstream(path) << R"(<Xdmf Version="3.0"><Domain><Grid GridType="Collection" CollectionType="Spatial">)" +
                             piece("p0", 0.0) + piece("p1", 2.0) + "</Grid></Domain></Xdmf>";
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(path);
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->GetNumberOfCells(), 2);
  const std::vector<BlockOfFile> blocks = recorded_blocks(grid);
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[1].name, "p1");
  for (double j : centre_jacobians(grid)) EXPECT_GT(j, 0.0);
}

TEST(XdmfReading, AMissingHeavyDataFileIsNamed) {
  const fs::path dir = test_temp_dir("xdmf_missing", true);
  const std::string path = copied(shaft, dir / "fenics_shaft.xdmf");
  const std::string error = read_error(path);
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find("fenics_shaft.h5"), std::string::npos) << error;
  EXPECT_NE(error.find("missing"), std::string::npos) << error;
}

TEST(XdmfReading, XmlThatIsNotXdmfIsSaidSo) {
  const std::string path = (test_temp_dir("xdmf") / "page.xdmf").string();
  std::ofstream(path) << "<?xml version=\"1.0\"?>\n<html><body>not a mesh</body></html>\n";
  const std::string error = read_error(path);
  EXPECT_NE(error.find(path + ": not an XDMF file"), std::string::npos) << error;
}

TEST(XdmfReading, ATruncatedHeavyDataFileIsSaidSo) {
  const fs::path dir = test_temp_dir("xdmf_truncated", true);
  const std::string path = copied(shaft, dir / "fenics_shaft.xdmf");
  {
    std::ifstream in(formats + "fenics_shaft.h5", std::ios::binary);
    std::string bytes(300000, '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    std::ofstream(dir / "fenics_shaft.h5", std::ios::binary) << bytes;
  }
  const std::string error = read_error(path);
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find("fenics_shaft.h5"), std::string::npos) << error;
}

// dolfinx 0.5 writes the mesh once as a grid of its own and each function
// as a temporal collection of grids that include it: one mesh, whose
// arrays at a time are all its functions' then.
TEST(XdmfReading, DolfinxsFunctionsShareTheirMesh) {
  ASSERT_EQ(xdmf_reader.times(dolfinx_plate), (std::vector<double>{1.0, 2.0}));
  const vtkSmartPointer<vtkUnstructuredGrid> first = read_grid(dolfinx_plate, 0), second = read_grid(dolfinx_plate, 1);
  ASSERT_TRUE(first && second);
  EXPECT_EQ(first->GetNumberOfPoints(), 1712);
  EXPECT_EQ(first->GetNumberOfCells(), 5795);
  vtkDataArray* stress = first->GetPointData()->GetArray("stress");
  ASSERT_TRUE(stress);
  ASSERT_TRUE(first->GetPointData()->GetArray("displacement"));
  EXPECT_EQ(first->GetPointData()->GetTensors(), stress);
  // Load factor 2 is twice load factor 1; the peak, Kirsch's 3σ and a
  // little more for the plate's width, on top of the hole.
  vtkDataArray* doubled = second->GetPointData()->GetArray("stress");
  ASSERT_TRUE(doubled);
  double peak = 0.0;
  vtkIdType at = -1;
  for (vtkIdType i = 0; i < stress->GetNumberOfTuples(); ++i) {
    EXPECT_NEAR(doubled->GetComponent(i, 0), 2.0 * stress->GetComponent(i, 0), 1e-9);
    const double l1 = eigenvalues(Sym3::symmetric_part(tensor_at(stress, i)))(0);
    if (l1 > peak) peak = l1, at = i;
  }
  EXPECT_NEAR(peak, 32.44, 0.01);
  double p[3];
  first->GetPoint(at, p);
  EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 0.01);  // on the hole
  EXPECT_GT(std::fabs(p[1]), 0.99);                 // at its top or bottom
}

}  // namespace
}  // namespace hsb
