// Data split over several files, as parallel and multiblock writers and
// time series leave it: pieces and blocks read as one body, a series at
// the step asked for.

#include <gtest/gtest.h>

#include <vtkDataSetTriangleFilter.h>
#include <vtkCellData.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkCompositeDataSet.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkExodusIIWriter.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <array>
#include <fstream>

#include "field/reading/data_error.h"
#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"
#include "tests/vtk_written.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

// Six different affine components: linear tetrahedra reproduce it exactly.
Sym3 linear_tensor(const Vec3& x, double scale = 1.0) {
  return Sym3{scale * (1 + 2 * x.x() - x.y()), 3 - x.z(), 0.5 + x.x() + x.y() + x.z(),
              0.25 * x.x(), -x.y() + 2 * x.z(), 1 - 0.5 * x.x()};
}

// Tetrahedra filling [x0, x0 + 0.25 (nx - 1)] × [0, 1] × [0, 1] ([0, 2]
// by default), with point tensors "stress".
vtkSmartPointer<vtkUnstructuredGrid> tet_body(double scale = 1.0, double x0 = 0.0, int nx = 9) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetOrigin(x0, 0, 0);
  image->SetDimensions(nx, 5, 5);
  image->SetSpacing(0.25, 0.25, 0.25);
  auto split = vtkSmartPointer<vtkDataSetTriangleFilter>::New();
  split->SetInputData(image);
  split->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = split->GetOutput();
  grid->GetPointData()->SetTensors(tensors_at_points(grid, "stress", [&](const Vec3& p) -> std::optional<Sym3> {
    return linear_tensor(p, scale);
  }));
  return grid;
}

std::string write_vtu(vtkUnstructuredGrid* grid, const std::string& name) {
  return written_by<vtkXMLUnstructuredGridWriter>(grid, test_temp_dir("composite") / name);
}

void expect_linear_field(const VtkData& data, double scale = 1.0) {
  ASSERT_TRUE(data.field);
  for (const Vec3& p : {Vec3(0.3, 0.4, 0.6), Vec3(1.7, 0.2, 0.9), Vec3(1.0, 0.5, 0.5)}) {
    const std::optional<Sym3> s = data.field->sample(p);
    ASSERT_TRUE(s) << p.transpose();
    EXPECT_LT((s->matrix() - linear_tensor(p, scale).matrix()).norm(), 1e-9) << p.transpose();
  }
}

// What a parallel run leaves: each process's piece, the second with a
// layer of ghost cells copied from the first, and the .pvtu naming them.
TEST(CompositeData, ParallelPiecesReadAsOneBodyWithoutInnerFaces) {
  const std::string whole = write_vtu(tet_body(), "whole.vtu");
  const auto ghost_array = [](vtkIdType cells) {
    auto ghosts = vtkSmartPointer<vtkUnsignedCharArray>::New();
    ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
    ghosts->SetNumberOfTuples(cells);
    ghosts->FillValue(0);
    return ghosts;
  };
  const vtkSmartPointer<vtkUnstructuredGrid> first = tet_body(1.0, 0.0, 5);  // x ∈ [0, 1]
  first->GetCellData()->AddArray(ghost_array(first->GetNumberOfCells()));
  write_vtu(first, "piece_0.vtu");
  // x ∈ [0.5, 2]: an even number of cells on, so split into tetrahedra as the first piece is
  const vtkSmartPointer<vtkUnstructuredGrid> second = tet_body(1.0, 0.5, 7);
  const vtkSmartPointer<vtkUnsignedCharArray> ghosts = ghost_array(second->GetNumberOfCells());
  int ghost_cells = 0;
  for (vtkIdType c = 0; c < second->GetNumberOfCells(); ++c) {
    double b[6];
    second->GetCellBounds(c, b);
    const bool ghost = b[1] <= 1.0;  // the first piece's cells
    ghosts->SetValue(c, ghost ? vtkDataSetAttributes::DUPLICATECELL : 0);
    ghost_cells += ghost;
  }
  ASSERT_GT(ghost_cells, 0);
  second->GetCellData()->AddArray(ghosts);
  write_vtu(second, "piece_1.vtu");
  const std::string path = (test_temp_dir("composite") / "pieces.pvtu").string();
  std::ofstream(path) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\">\n"
                      << "<PUnstructuredGrid GhostLevel=\"1\">\n"
                      << "<PPointData Tensors=\"stress\"><PDataArray type=\"Float64\" Name=\"stress\" "
                         "NumberOfComponents=\"6\"/></PPointData>\n"
                      << "<PCellData><PDataArray type=\"UInt8\" Name=\"vtkGhostType\"/></PCellData>\n"
                      << "<PPoints><PDataArray type=\"Float32\" NumberOfComponents=\"3\"/></PPoints>\n"
                      << "<Piece Source=\"piece_0.vtu\"/>\n<Piece Source=\"piece_1.vtu\"/>\n"
                      << "</PUnstructuredGrid>\n</VTKFile>\n";

  const VtkData pieces = load_vtk_data({path});
  expect_linear_field(pieces);
  // The pieces' shared points are joined: the shell is the body's outside
  // alone, as from the one file.
  const VtkData one = load_vtk_data({whole});
  EXPECT_EQ(pieces.boundary.triangles.size(), one.boundary.triangles.size());
}

TEST(CompositeData, BlocksReadAsOneBody) {
  const vtkSmartPointer<vtkUnstructuredGrid> body = tet_body();
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, tet_body(1.0, 0.0, 5));  // x ∈ [0, 1]
  blocks->SetBlock(1, tet_body(1.0, 1.0, 5));  // x ∈ [1, 2], sharing the plane x = 1
  const std::string path = written_by<vtkXMLMultiBlockDataWriter>(blocks, test_temp_dir("composite") / "blocks.vtm");
  const VtkData data = load_vtk_data({path});
  expect_linear_field(data);
  const VtkData one = load_vtk_data({write_vtu(body, "whole_for_blocks.vtu")});
  EXPECT_EQ(data.boundary.triangles.size(), one.boundary.triangles.size());
}

// data.block reads one block of a multiblock file, by its name or its
// index; a name that is none of them is an error listing them.
TEST(CompositeData, OneBlockIsReadWhenTheSceneNamesIt) {
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, tet_body(1.0, 0.0, 5));  // x ∈ [0, 1]
  blocks->SetBlock(1, tet_body(1.0, 1.0, 5));  // x ∈ [1, 2]
  blocks->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "left");
  blocks->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "right");
  const std::string path =
      written_by<vtkXMLMultiBlockDataWriter>(blocks, test_temp_dir("composite") / "named_blocks.vtm");
  const Vec3 in_left(0.3, 0.4, 0.6), in_right(1.7, 0.2, 0.9);

  VtkFileSpec spec{path};
  const std::string described = describe_vtk_file(spec);
  EXPECT_NE(described.find("blocks    2 with cells: 0 \"left\" (320 cells), 1 \"right\" (320 cells); all merged"),
            std::string::npos)
      << described;
  for (const std::string right : {"right", "1"}) {
    spec.block = right;
    const VtkData data = load_vtk_data(spec);
    ASSERT_TRUE(data.field);
    EXPECT_FALSE(data.field->sample(in_left)) << right;
    ASSERT_TRUE(data.field->sample(in_right)) << right;
    EXPECT_LT((data.field->sample(in_right)->matrix() - linear_tensor(in_right, 1.0).matrix()).norm(), 1e-9);
    EXPECT_NEAR(data.field->bounds().lo.x(), 1.0, 1e-6);
  }
  spec.block = "left";
  EXPECT_TRUE(load_vtk_data(spec).field->sample(in_left));
  EXPECT_NE(describe_vtk_file(spec).find("only \"left\" read (data.block)"), std::string::npos);
  spec.block = "middle";
  try {
    load_vtk_data(spec);
    FAIL() << "read a block the file does not have";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("data.block \"middle\" names none of its 2 blocks with cells: 0 \"left\", 1 \"right\""),
              std::string::npos)
        << e.what();
  }
  // A file of one data set has no blocks to pick.
  spec = VtkFileSpec{write_vtu(tet_body(), "one_block.vtu")};
  spec.block = "0";
  try {
    load_vtk_data(spec);
    FAIL() << "picked a block of a file without blocks";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("data.block applies only to files of blocks"), std::string::npos) << e.what();
  }
}

TEST(CompositeData, ATimeSeriesIsReadAtTheStepAskedFor) {
  const std::string a = write_vtu(tet_body(1.0), "series_0.vtu");
  const std::string b = write_vtu(tet_body(5.0), "series_1.vtu");
  const std::string path = (test_temp_dir("composite") / "series.pvd").string();
  // Listed out of order: the series is in the order of time.
  std::ofstream(path) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n"
                      << "<DataSet timestep=\"0.5\" part=\"0\" file=\"series_1.vtu\"/>\n"
                      << "<DataSet timestep=\"0\" part=\"0\" file=\"series_0.vtu\"/>\n"
                      << "</Collection>\n</VTKFile>\n";
  EXPECT_EQ(series_times(path), (std::vector<double>{0.0, 0.5}));
  EXPECT_TRUE(series_times(a).empty());
  VtkFileSpec spec{path};
  expect_linear_field(load_vtk_data(spec), 1.0);  // no step: the first
  spec.step = 1;
  expect_linear_field(load_vtk_data(spec), 5.0);
  spec.step = 2;
  try {
    load_vtk_data(spec);
    FAIL() << "step 2 of 2 read";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("data.step 2 is beyond its 2 steps (0 to 1)"), std::string::npos) << e.what();
  }
  spec = VtkFileSpec{b};
  spec.step = 1;
  EXPECT_THROW(load_vtk_data(spec), DataError);  // a single data set has no step 1
}

// `grid`'s tensors as six scalar arrays named `names` (for XX, YY, ZZ,
// XY, YZ, XZ), added in the order `file_order` gives.
void split_into_components(vtkUnstructuredGrid* grid, const std::array<std::string, 6>& names,
                           const std::array<int, 6>& file_order) {
  vtkDataArray* stress = grid->GetPointData()->GetArray("stress");
  for (int c : file_order) {
    auto part = vtkSmartPointer<vtkDoubleArray>::New();
    part->SetName(names[std::size_t(c)].c_str());
    part->SetNumberOfTuples(stress->GetNumberOfTuples());
    for (vtkIdType i = 0; i < stress->GetNumberOfTuples(); ++i) part->SetValue(i, stress->GetComponent(i, c));
    grid->GetPointData()->AddArray(part);
  }
  grid->GetPointData()->RemoveArray("stress");
}

// `data` (a grid, or blocks of grids) written as Exodus II.
std::string write_exodus(vtkDataObject* data, const std::string& file) {
  return written_by<vtkExodusIIWriter>(data, test_temp_dir("composite") / file);
}

const std::array<std::string, 6> sierra_names{"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_zx"};

// Exodus II as Sierra writes it (stress_xx, ..., stress_zx) and as a
// writer that lists the upper triangle row by row (stressXX, stressXY,
// ...), which VTK's own reader gloms into a vector "stressX" and three
// scalars: both read as the one tensor they are, with the order recorded.
TEST(CompositeData, ExodusComponentVariablesReadAsOneTensor) {
  const std::array<int, 6> sierra{0, 1, 2, 3, 4, 5}, upper_rows{0, 3, 5, 1, 4, 2};
  for (const auto& [names, order] :
       {std::pair{sierra_names, sierra},
        std::pair{std::array<std::string, 6>{"stressXX", "stressYY", "stressZZ", "stressXY", "stressYZ", "stressXZ"}, upper_rows}}) {
    const vtkSmartPointer<vtkUnstructuredGrid> body = tet_body();
    split_into_components(body, names, order);
    VtkFileSpec spec{write_exodus(body, names[0] + ".exo")};
    const std::string described = describe_vtk_file(spec);
    SCOPED_TRACE(described);
    EXPECT_NE(described.find("tensors   \"stress\" (6 components"), std::string::npos);
    EXPECT_NE(described.find("order     recorded in the file"), std::string::npos);
    const VtkData data = load_vtk_data(spec);
    EXPECT_TRUE(data.warnings.empty());
    expect_linear_field(data);
    spec.components = "sfepy";  // the file says which is which: an order given too is refused
    EXPECT_THROW(load_vtk_data(spec), DataError);
    spec.components = "";
    spec.step = 3;  // the file has one step
    EXPECT_THROW(load_vtk_data(spec), DataError);
  }
}

// An Exodus file's element blocks, merged or one alone.
TEST(CompositeData, OneExodusElementBlockIsReadWhenTheSceneNamesIt) {
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetNumberOfBlocks(2);
  for (unsigned i : {0u, 1u}) {
    const vtkSmartPointer<vtkUnstructuredGrid> half = tet_body(1.0, double(i), 5);  // x ∈ [i, i + 1]
    split_into_components(half, sierra_names, {0, 1, 2, 3, 4, 5});
    blocks->SetBlock(i, half);
  }
  VtkFileSpec spec{write_exodus(blocks, "two_blocks.exo")};
  expect_linear_field(load_vtk_data(spec));
  spec.block = "1";
  const VtkData right = load_vtk_data(spec);
  EXPECT_FALSE(right.field->sample(Vec3(0.3, 0.4, 0.6)));
  EXPECT_TRUE(right.field->sample(Vec3(1.7, 0.2, 0.9)));
  EXPECT_NE(describe_vtk_file(spec).find("blocks    2 with cells"), std::string::npos);
}

// meshio's Exodus writer makes files whose variables the Exodus library
// cannot find ("could not find nodal variables"), and VTK's reader then
// hands on uninitialised memory as values, silently: such a file is refused.
TEST(CompositeData, AnExodusFileTheExodusLibraryCannotReadIsRefused) {
  const std::string path = std::string(HSB_SOURCE_DIR) + "/tests/field/data/meshio_nodal_variables.e";
  try {
    load_vtk_data({path});
    FAIL() << "read values the Exodus library could not";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("the Exodus library cannot read its nodal variable 1"), std::string::npos)
        << e.what();
  }
}

TEST(CompositeData, ASeriesThatIsNotOneIsSaidSo) {
  const std::string path = (test_temp_dir("composite") / "broken.pvd").string();
  std::ofstream(path) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n</VTKFile>\n";
  EXPECT_THROW(series_times(path), DataError);
  EXPECT_THROW(load_vtk_data({path}), DataError);
}

}  // namespace
}  // namespace hsb
