// Reading tensor data from VTK files: every format and encoding VTK's own
// writers produce, every cell kind, point and cell data, 6 and 9 components,
// and the errors a user can meet.

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataSetTriangleFilter.h>
#include <vtkDataSetWriter.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "field/glyph_pipeline.h"
#include "field/reading/data_error.h"
#include "field/reading/vtk_data.h"
#include "field/tensor/eigensystem.h"
#include "field/tracing/trajectory.h"
#include "tests/temp_dir.h"
#include "tests/vtk_written.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
  return test_temp_dir("vtk_test");
}

// A tensor field whose six components are different affine functions of x:
// every linear cell type must reproduce it exactly.
Sym3 linear_tensor(const Vec3& x) {
  return Sym3{1 + 2 * x.x() - x.y(), 3 - x.z(), 0.5 + x.x() + x.y() + x.z(),
              0.25 * x.x(), -x.y() + 2 * x.z(), 1 - 0.5 * x.x()};
}

// As nine components (row-major), the layout most files use.
void set_tensor(vtkDoubleArray* a, vtkIdType i, const Sym3& s) {
  const Mat3 m = s.matrix();
  double t[9];
  for (int k = 0; k < 9; ++k) t[k] = m(k / 3, k % 3);
  a->SetTuple(i, t);
}

vtkSmartPointer<vtkDoubleArray> tensor_array(const char* name, int components, vtkIdType n) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(n);
  return a;
}

// Attaches point tensors (named "stress", also the active tensors) from f.
template <class F>
void add_point_tensors(vtkDataSet* data, F f) {
  auto a = tensor_array("stress", 9, data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    set_tensor(a, i, f(Vec3(p[0], p[1], p[2])));
  }
  data->GetPointData()->SetTensors(a);
}

vtkSmartPointer<vtkImageData> image(int n) {
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(n, n + 1, n + 2);
  img->SetOrigin(-1, 0, 0.5);
  img->SetSpacing(0.5, 0.25, 0.5);
  return img;
}

// Hexahedra on a jittered n³ lattice: not axis-aligned, still exact for
// linear fields (isoparametric cells reproduce linear functions). The jitter
// is in eighths, so even the legacy ASCII writer's six digits keep every
// coordinate and tensor value exact.
vtkSmartPointer<vtkUnstructuredGrid> hex_mesh(int n, unsigned seed = 7) {
  std::mt19937 rng(seed);
  auto jitter = [](std::mt19937& r) { return 0.125 * double(int(r() % 3u) - 1); };
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto id = [n](int i, int j, int k) { return vtkIdType(i + (n + 1) * (j + (n + 1) * k)); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const bool inner = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        points->InsertNextPoint(i + (inner ? jitter(rng) : 0), j + (inner ? jitter(rng) : 0),
                                k + (inner ? jitter(rng) : 0));
      }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const vtkIdType hex[8] = {id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                                  id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      }
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> tet_mesh(int n) {
  auto split = vtkSmartPointer<vtkDataSetTriangleFilter>::New();
  split->SetInputData(hex_mesh(n));
  split->Update();
  return split->GetOutput();
}

// One hexahedron, wedge, pyramid and tetrahedron side by side.
vtkSmartPointer<vtkUnstructuredGrid> mixed_mesh() {
  auto points = vtkSmartPointer<vtkPoints>::New();
  const double p[][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1},
                         {2, 0, 0}, {2, 1, 0}, {1.5, 0.5, 1.5}, {2, 0, 1}, {2, 1, 1}, {3, 0, 0}};
  for (const auto& q : p) points->InsertNextPoint(q);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  const vtkIdType hex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  const vtkIdType wedge[6] = {1, 8, 5, 2, 9, 6};
  const vtkIdType pyramid[5] = {5, 11, 12, 6, 10};
  const vtkIdType tet[4] = {8, 13, 9, 11};
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  grid->InsertNextCell(VTK_WEDGE, 6, wedge);
  grid->InsertNextCell(VTK_PYRAMID, 5, pyramid);
  grid->InsertNextCell(VTK_TETRA, 4, tet);
  return grid;
}

vtkSmartPointer<vtkStructuredGrid> structured(int n) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) points->InsertNextPoint(i + 0.2 * j, j, k + 0.1 * i);  // sheared
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetDimensions(n + 1, n + 1, n + 1);
  grid->SetPoints(points);
  return grid;
}

// Writes `data` as an XML unstructured grid in the test folder.
fs::path write_vtu(vtkUnstructuredGrid* data, const std::string& name) {
  return written_by<vtkXMLUnstructuredGridWriter>(data, temp_dir() / name);
}

fs::path write_vti(vtkImageData* data, const std::string& name) {
  return written_by<vtkXMLImageDataWriter>(data, temp_dir() / name);
}

VtkData load(const fs::path& path, const std::string& array = "", CellTensors cells = CellTensors::constant,
             TensorAssociation where = TensorAssociation::automatic) {
  return load_vtk_data({path.string(), array, where, cells});
}

double distance(const Sym3& a, const Sym3& b) { return (a.matrix() - b.matrix()).norm(); }

// Every point of `data` samples back to its tensor.
void expect_nodes_read_back(const VtkData& loaded, vtkDataSet* data) {
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    const Vec3 x(p[0], p[1], p[2]);
    const std::optional<Sym3> s = loaded.field->sample(x);
    ASSERT_TRUE(s.has_value()) << "point " << i;
    EXPECT_LT(distance(*s, linear_tensor(x)), 1e-10) << "point " << i;
  }
}

// Every way VTK writes these data sets, read back identically.
TEST(VtkData, EveryFormatAndEncodingReadsBack) {
  std::vector<std::pair<std::string, vtkSmartPointer<vtkDataSet>>> sets = {
      {"image", image(3)}, {"hexes", hex_mesh(2)}, {"tets", tet_mesh(2)}, {"mixed", mixed_mesh()},
      {"structured", structured(2)}};
  int files = 0;
  for (auto& [name, data] : sets) {
    add_point_tensors(data, linear_tensor);
    SCOPED_TRACE(name);
    // Legacy, ASCII and binary, in both file versions VTK 9 writes.
    for (int binary = 0; binary < 2; ++binary) {
      for (int version : {42, 51}) {
        const fs::path path = temp_dir() / (name + "_legacy" + std::to_string(binary) + "_" + std::to_string(version) + ".vtk");
        auto writer = vtkSmartPointer<vtkDataSetWriter>::New();
        writer->SetInputData(data);
        writer->SetFileName(path.string().c_str());
        writer->SetFileVersion(version);
        binary ? writer->SetFileTypeToBinary() : writer->SetFileTypeToASCII();
        ASSERT_EQ(writer->Write(), 1);
        SCOPED_TRACE(path.string());
        expect_nodes_read_back(load(path), data);
        ++files;
      }
    }
    // XML: ASCII, inline binary and appended, each raw and zlib-compressed.
    vtkSmartPointer<vtkXMLWriter> xml;
    std::string ext;
    if (name == "image") {
      xml = vtkSmartPointer<vtkXMLImageDataWriter>::New();
      ext = ".vti";
    } else if (name == "structured") {
      xml = vtkSmartPointer<vtkXMLStructuredGridWriter>::New();
      ext = ".vts";
    } else {
      xml = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
      ext = ".vtu";
    }
    for (int mode = 0; mode < 3; ++mode) {
      for (int zlib = 0; zlib < 2; ++zlib) {
        const fs::path path = temp_dir() / (name + "_xml" + std::to_string(mode) + std::to_string(zlib) + ext);
        xml->SetInputData(data);
        xml->SetFileName(path.string().c_str());
        mode == 0 ? xml->SetDataModeToAscii() : mode == 1 ? xml->SetDataModeToBinary() : xml->SetDataModeToAppended();
        zlib ? xml->SetCompressorTypeToZLib() : xml->SetCompressorTypeToNone();
        ASSERT_EQ(xml->Write(), 1);
        SCOPED_TRACE(path.string());
        expect_nodes_read_back(load(path), data);
        ++files;
      }
    }
  }
  EXPECT_EQ(files, 5 * (4 + 6));
}

class LinearFieldOnMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(LinearFieldOnMesh, IsReproducedExactlyAnywhereInside) {
  vtkSmartPointer<vtkUnstructuredGrid> mesh =
      GetParam() == "tets" ? tet_mesh(3) : GetParam() == "hexes" ? hex_mesh(3) : mixed_mesh();
  add_point_tensors(mesh, linear_tensor);
  const fs::path path = write_vtu(mesh, ("linear_" + GetParam() + ".vtu"));
  const VtkData loaded = load(path);

  // Random points inside random cells (by random barycentric mixtures of
  // each cell's corners, which lie inside a convex cell).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int inside = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    vtkCell* cell = mesh->GetCell(vtkIdType(rng() % std::uint32_t(mesh->GetNumberOfCells())));
    Vec3 x = Vec3::Zero();
    double total = 0.0;
    for (vtkIdType k = 0; k < cell->GetNumberOfPoints(); ++k) {
      const double w = u(rng);
      double p[3];
      mesh->GetPoint(cell->GetPointId(int(k)), p);
      x += w * Vec3(p[0], p[1], p[2]);
      total += w;
    }
    x /= total;
    const std::optional<Sym3> s = loaded.field->sample(x);
    if (!s) continue;  // a jittered hex can be slightly non-convex
    ++inside;
    EXPECT_LT(distance(*s, linear_tensor(x)), 1e-9) << x.transpose();
  }
  EXPECT_GT(inside, 1900);
  EXPECT_FALSE(loaded.field->sample(Vec3(-0.5, 0.5, 0.5)).has_value());  // outside
}

INSTANTIATE_TEST_SUITE_P(CellKinds, LinearFieldOnMesh, ::testing::Values("tets", "hexes", "mixed"));

// Quadratic cells carry quadratic fields through VTK's own interpolation
// functions: a 10-node tetrahedron and a 20-node hexahedron. Not to round-off
// as linear cells do: VTK finds the parametric coordinates in nonlinear cells
// by a Newton iteration stopped at about 1e-3, so the field is reproduced to
// about that; interpolating the corners linearly would miss by about 0.1.
TEST(VtkData, QuadraticCellsReproduceQuadraticFields) {
  auto quadratic = [](const Vec3& x) {
    return Sym3{x.x() * x.x(), x.y() * x.z(), 1 + x.z() * x.z() - x.x(), x.x() * x.y(), 2 * x.y() * x.y(), x.z()};
  };
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  // Tetrahedron: corners, then mid-edges 01, 12, 20, 03, 13, 23.
  const Vec3 c[4] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (const Vec3& p : c) points->InsertNextPoint(p.x(), p.y(), p.z());
  for (const auto& e : edges) {
    const Vec3 m = 0.5 * (c[e[0]] + c[e[1]]);
    points->InsertNextPoint(m.x(), m.y(), m.z());
  }
  vtkIdType tet[10];
  for (int i = 0; i < 10; ++i) tet[i] = i;
  // Hexahedron on [2,3]×[0,1]×[0,1]: corners, then mid-edges of the bottom,
  // top and vertical edges (VTK's order).
  const Vec3 h[8] = {Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(3, 1, 0), Vec3(2, 1, 0),
                     Vec3(2, 0, 1), Vec3(3, 0, 1), Vec3(3, 1, 1), Vec3(2, 1, 1)};
  const int hex_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  vtkIdType hex[20];
  for (int i = 0; i < 8; ++i) hex[i] = points->InsertNextPoint(h[i].x(), h[i].y(), h[i].z());
  for (int i = 0; i < 12; ++i) {
    const Vec3 m = 0.5 * (h[hex_edges[i][0]] + h[hex_edges[i][1]]);
    hex[8 + i] = points->InsertNextPoint(m.x(), m.y(), m.z());
  }
  mesh->SetPoints(points);
  mesh->InsertNextCell(VTK_QUADRATIC_TETRA, 10, tet);
  mesh->InsertNextCell(VTK_QUADRATIC_HEXAHEDRON, 20, hex);
  add_point_tensors(mesh, quadratic);
  const VtkData loaded = load(write_vtu(mesh, "quadratic.vtu"));

  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 300; ++i) {
    // Inside the tetrahedron: a random convex mixture of its corners.
    double w[4], total = 0;
    for (double& x : w) total += (x = u(rng));
    Vec3 x = Vec3::Zero();
    for (int k = 0; k < 4; ++k) x += w[k] / total * c[k];
    ASSERT_TRUE(loaded.field->sample(x).has_value()) << x.transpose();
    EXPECT_LT(distance(*loaded.field->sample(x), quadratic(x)), 2e-3) << x.transpose();
    // Inside the hexahedron.
    const Vec3 y(2 + u(rng), u(rng), u(rng));
    ASSERT_TRUE(loaded.field->sample(y).has_value()) << y.transpose();
    EXPECT_LT(distance(*loaded.field->sample(y), quadratic(y)), 2e-3) << y.transpose();
  }
}

// Image data turned by a Direction matrix: the grid is sampled in its own
// frame (it once fell to a cell locator that found no cell in it, and a
// scene showed the shell alone).
// A uniform grid turned by `turn` about z, with the affine tensor field.
vtkSmartPointer<vtkImageData> turned_image(double turn, const fs::path& path) {
  auto img = image(4);
  const double d[9] = {std::cos(turn), -std::sin(turn), 0, std::sin(turn), std::cos(turn), 0, 0, 0, 1};
  img->SetDirectionMatrix(d);
  add_point_tensors(img, linear_tensor);
  written_by<vtkXMLImageDataWriter>(img, path);
  return img;
}

TEST(VtkData, ATurnedImageIsSampledInItsOwnFrame) {
  const double turn = 30.0 * M_PI / 180.0;
  const fs::path path = temp_dir() / "turned.vti";
  turned_image(turn, path);
  const VtkData data = load(path);
  ASSERT_TRUE(data.field);
  // Inside the turned grid, at points given in its own frame: the affine
  // field exactly.
  Mat3 direction;
  direction << std::cos(turn), -std::sin(turn), 0, std::sin(turn), std::cos(turn), 0, 0, 0, 1;
  const Vec3 origin(-1, 0, 0.5), extent(0.5 * 3, 0.25 * 4, 0.5 * 5);
  int inside = 0;
  for (double a = 0.05; a < 1.0; a += 0.15)
    for (double b = 0.05; b < 1.0; b += 0.2) {
      const Vec3 x = origin + direction * Vec3(a * extent.x(), b * extent.y(), (1 - a) * extent.z());
      const std::optional<Sym3> s = data.field->sample(x);
      ASSERT_TRUE(s) << "no data at " << x.transpose();
      EXPECT_LT((s->matrix() - linear_tensor(x).matrix()).norm(), 1e-9) << x.transpose();
      ++inside;
    }
  EXPECT_GT(inside, 30);
  // Inside the box around it but outside the grid: no data.
  const Box3 box = data.field->bounds();
  const Vec3 beside = origin + direction * Vec3(0.9 * extent.x(), -0.1, 0.5 * extent.z());
  EXPECT_TRUE(box.contains(beside));
  EXPECT_FALSE(data.field->sample(beside));
  // The box holds the turned grid's corners.
  for (int c = 0; c < 8; ++c) {
    const Vec3 p = origin + direction * Vec3(c & 1 ? extent.x() : 0, c & 2 ? extent.y() : 0, c & 4 ? extent.z() : 0);
    EXPECT_TRUE(box.contains(p) || (p - box.lo.cwiseMax(box.hi.cwiseMin(p))).norm() < 1e-12) << p.transpose();
  }
}

// glyphs.placement = "points": the values where they stand. A turned
// image's nodes in its own frame, cell data at the cells' centres; every
// stride-th one becomes a glyph of the tensor there.
TEST(VtkData, SitesAreWhereTheValuesStand) {
  const fs::path turned = temp_dir() / "turned_sites.vti";
  const vtkSmartPointer<vtkImageData> img = turned_image(30.0 * M_PI / 180.0, turned);
  VtkFileSpec spec{turned.string()};
  EXPECT_TRUE(load_vtk_data(spec).sites.positions.empty());  // only when asked
  spec.sites = true;
  const VtkData nodes = load_vtk_data(spec);
  ASSERT_EQ(nodes.sites.positions.size(), std::size_t(img->GetNumberOfPoints()));
  for (std::size_t i = 0; i < nodes.sites.positions.size(); ++i) {
    const Vec3 p = nodes.sites.positions[i];
    double vtk[3];
    img->GetPoint(vtkIdType(i), vtk);  // the grid's nodes, computed, are VTK's points
    EXPECT_LT((p - Vec3(vtk[0], vtk[1], vtk[2])).norm(), 1e-14) << i;
    EXPECT_TRUE(nodes.field->sample(p)) << p.transpose();  // in the turned grid, not beside it
    EXPECT_LT(distance(nodes.sites.tensors[i], linear_tensor(p)), 1e-9) << p.transpose();
  }

  // An extent that starts away from index 0, unturned: VTK's own arithmetic.
  auto shifted = image(3);
  shifted->SetExtent(2, 4, -1, 1, 5, 7);
  shifted->SetOrigin(-0.3, 1e6, 7.25);
  add_point_tensors(shifted, linear_tensor);
  const fs::path shifted_path = temp_dir() / "shifted_sites.vti";
  written_by<vtkXMLImageDataWriter>(shifted, shifted_path);
  VtkFileSpec shifted_spec{shifted_path.string()};
  shifted_spec.sites = true;
  const VtkData shifted_nodes = load_vtk_data(shifted_spec);
  ASSERT_EQ(shifted_nodes.sites.positions.size(), std::size_t(shifted->GetNumberOfPoints()));
  for (std::size_t i = 0; i < shifted_nodes.sites.positions.size(); ++i) {
    double vtk[3];
    shifted->GetPoint(vtkIdType(i), vtk);
    EXPECT_EQ(shifted_nodes.sites.positions[i], Vec3(vtk[0], vtk[1], vtk[2])) << i;
  }

  auto mesh = hex_mesh(2);
  auto cells = tensor_array("cellstress", 9, mesh->GetNumberOfCells());
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c) set_tensor(cells, c, (1.0 + double(c)) * Sym3{1, 2, 3, 0, 0, 0});
  mesh->GetCellData()->SetTensors(cells);
  GlyphPipelineSpec glyphs;
  glyphs.data.kind = DataKind::vtk_file;
  glyphs.data.file.path = write_vtu(mesh, "cell_sites.vtu").string();
  glyphs.placement = SourcePlacement::at_data_points;
  glyphs.color = ColorScalar::lambda1;
  const GlyphScene all = build_glyph_scene(glyphs, 1.0);
  ASSERT_EQ(all.sources.size(), std::size_t(mesh->GetNumberOfCells()));
  EXPECT_EQ(all.values.stride, 1);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c) {
    const GlyphSource& g = all.sources[std::size_t(c)];
    EXPECT_NEAR(g.scalar, 3.0 * (1.0 + double(c)), 1e-9);  // λ1 of the cell's own tensor
    double b[6];
    mesh->GetCellBounds(c, b);
    EXPECT_TRUE(Box3({Vec3(b[0], b[2], b[4]), Vec3(b[1], b[3], b[5])}).contains(g.centre)) << c;
  }
  glyphs.stride = 3;
  const GlyphScene every_third = build_glyph_scene(glyphs, 1.0);
  ASSERT_EQ(every_third.sources.size(), std::size_t((mesh->GetNumberOfCells() + 2) / 3));
  EXPECT_EQ(every_third.sources[1].centre, all.sources[3].centre);
}

TEST(VtkData, SixAndNineComponentsGiveTheSameEigensystem) {
  auto mesh = tet_mesh(2);
  auto six = tensor_array("six", 6, mesh->GetNumberOfPoints());
  auto nine = tensor_array("nine", 9, mesh->GetNumberOfPoints());
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) {
    const Sym3 s{g(rng), g(rng), g(rng), g(rng), g(rng), g(rng)};
    const double t6[6] = {s.xx, s.yy, s.zz, s.xy, s.yz, s.xz};  // VTK's order
    six->SetTuple(i, t6);
    set_tensor(nine, i, s);
  }
  mesh->GetPointData()->AddArray(six);
  mesh->GetPointData()->AddArray(nine);
  const fs::path path = write_vtu(mesh, "six_nine.vtu");
  const VtkData a = load(path, "six"), b = load(path, "nine");
  for (double t = 0.1; t < 2; t += 0.13) {
    const Vec3 x(t, 2 - t, 0.5 + 0.3 * t);
    const Eigensystem ea = decompose(*a.field->sample(x)), eb = decompose(*b.field->sample(x));
    EXPECT_LT((ea.values - eb.values).norm(), 1e-12);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::fabs(ea.vectors.col(k).dot(eb.vectors.col(k))), 1.0, 1e-9);
  }
}

TEST(VtkData, CellDataIsPiecewiseConstantOrAveragedOntoPoints) {
  auto mesh = hex_mesh(2);
  auto cells = tensor_array("cellstress", 9, mesh->GetNumberOfCells());
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c) set_tensor(cells, c, (1.0 + double(c)) * Sym3{1, 2, 3, 0, 0, 0});
  mesh->GetCellData()->SetTensors(cells);
  const fs::path path = write_vtu(mesh, "cells.vtu");

  const VtkData constant = load(path);  // active tensors: the cell array
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c) {
    double centre[3] = {0, 0, 0};
    vtkCell* cell = mesh->GetCell(c);
    for (int k = 0; k < 8; ++k) {
      double p[3];
      mesh->GetPoint(cell->GetPointId(k), p);
      for (int d = 0; d < 3; ++d) centre[d] += p[d] / 8;
    }
    const Sym3 s = *constant.field->sample(Vec3(centre[0], centre[1], centre[2]));
    EXPECT_NEAR(s.xx, 1.0 + double(c), 1e-12);
  }
  // Averaged: the outer corner (0,0,0) touches cell 0 only; the centre node
  // (lattice point 13, jittered) touches all eight, whose mean factor is 4.5.
  const VtkData averaged = load(path, "", CellTensors::averaged);
  EXPECT_NEAR(averaged.field->sample(Vec3(0, 0, 0))->xx, 1.0, 1e-9);
  double node[3];
  mesh->GetPoint(13, node);
  EXPECT_NEAR(averaged.field->sample(Vec3(node[0], node[1], node[2]))->zz, 3 * 4.5, 1e-9);
  EXPECT_THROW(load(path, "", CellTensors::constant, TensorAssociation::point), DataError);
}

TEST(VtkData, AsymmetricTensorsGiveTheirSymmetricPartAndOneWarning) {
  auto mesh = tet_mesh(1);
  auto a = tensor_array("t", 9, mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) {
    double t[9] = {1, 2, 0, 0, 1, 0, 0, 0, 1};  // T01 = 2, T10 = 0
    t[3] = i == 3 ? -1.0 : 0.0;                   // largest asymmetry (3) at point 3
    a->SetTuple(i, t);
  }
  mesh->GetPointData()->SetTensors(a);
  const fs::path path = write_vtu(mesh, "asym.vtu");
  const VtkData loaded = load(path);
  ASSERT_EQ(loaded.warnings.size(), 1u);
  EXPECT_NE(loaded.warnings[0].find("not symmetric"), std::string::npos);
  EXPECT_NE(loaded.warnings[0].find("= 3 at point 3"), std::string::npos) << loaded.warnings[0];
  double p[3];
  mesh->GetPoint(0, p);
  EXPECT_NEAR(loaded.field->sample(Vec3(p[0], p[1], p[2]))->xy, 1.0, 1e-12);  // (2 + 0)/2
}

TEST(VtkData, AnInfiniteValueIsAnErrorNamingThePoint) {
  auto mesh = tet_mesh(1);
  add_point_tensors(mesh, linear_tensor);
  mesh->GetPointData()->GetTensors()->SetComponent(5, 4, INFINITY);
  const fs::path path = write_vtu(mesh, "inf.vtu");
  try {
    load(path);
    FAIL() << "no error";
  } catch (const DataError& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() + ": array \"stress\" has a non-finite value (inf) at point 5, component 4");
  }
}

// NaN is how diffusion tools mark the voxels outside a brain mask: no data
// there, as outside the mesh, said once; a file of nothing else is refused.
TEST(VtkData, NaNIsNoDataAndAllNaNIsAnError) {
  auto img = image(4);
  add_point_tensors(img, linear_tensor);
  vtkDataArray* tensors = img->GetPointData()->GetTensors();
  tensors->SetComponent(0, 4, std::nan(""));  // the corner node (0, 0, 0)
  const VtkData loaded = load(write_vti(img, "masked.vti"));
  ASSERT_EQ(loaded.warnings.size(), 1u);
  EXPECT_NE(loaded.warnings[0].find("1 of " + std::to_string(img->GetNumberOfPoints()) +
                                    " points have no tensor (NaN in array \"stress\"): no data there"),
            std::string::npos)
      << loaded.warnings[0];
  double p0[3], far[3];
  img->GetPoint(0, p0);
  img->GetPoint(img->GetNumberOfPoints() - 1, far);
  const Vec3 near_corner = Vec3(p0[0], p0[1], p0[2]) + 0.1 * (Vec3(far[0], far[1], far[2]) - Vec3(p0[0], p0[1], p0[2])) / 4.0;
  EXPECT_FALSE(loaded.field->sample(near_corner)) << "the cell at the NaN node is no data";
  const Vec3 inside = 0.5 * (Vec3(p0[0], p0[1], p0[2]) + Vec3(far[0], far[1], far[2]));
  ASSERT_TRUE(loaded.field->sample(inside));
  EXPECT_LT((loaded.field->sample(inside)->matrix() - linear_tensor(inside).matrix()).norm(), 1e-9);
  for (vtkIdType i = 0; i < img->GetNumberOfPoints(); ++i) tensors->SetComponent(i, 0, std::nan(""));
  const fs::path all = write_vti(img, "all_nan.vti");
  try {
    load(all);
    FAIL() << "an all-NaN file loaded";
  } catch (const DataError& e) {
    EXPECT_EQ(std::string(e.what()), all.string() + ": array \"stress\" holds no data: every point's tensor is NaN");
  }
}

TEST(VtkData, MissingArrayListsTheArraysThereAre) {
  auto mesh = tet_mesh(1);
  add_point_tensors(mesh, linear_tensor);
  auto other = tensor_array("displacement", 3, mesh->GetNumberOfPoints());
  mesh->GetPointData()->AddArray(other);
  const fs::path path = write_vtu(mesh, "arrays.vtu");
  try {
    load(path, "strain");
    FAIL() << "no error";
  } catch (const DataError& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() + ": no array named \"strain\" (data.array); the file has point data: stress (9 components), "
                              "displacement (3 components); cell data: none");
  }
  // Three components name a vector field: a flow, for streamballs.
  const VtkData vectors = load(path, "displacement");
  EXPECT_TRUE(vectors.vectors);
  EXPECT_FALSE(vectors.field);
  // Unless tensors were asked for.
  VtkFileSpec tensors_only;
  tensors_only.path = path.string();
  tensors_only.array = "displacement";
  tensors_only.kind = FieldKind::tensor;
  try {
    load_vtk_data(tensors_only);
    FAIL() << "no error";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("has 3 components; a tensor needs 9, or 6"), std::string::npos) << e.what();
  }
}

TEST(VtkData, UnreadableFilesAreOneClearError) {
  const fs::path garbage = temp_dir() / "garbage.vtu";
  std::ofstream(garbage) << "this is not VTK\n";
  EXPECT_THROW(load(garbage), DataError);
  EXPECT_THROW(load(temp_dir() / "missing.vtu"), DataError);
  EXPECT_THROW(load(temp_dir() / "file.stl"), DataError);
  try {
    load(garbage);
  } catch (const DataError& e) {
    EXPECT_EQ(std::string(e.what()), garbage.string() + ": not a VTK XML file: it does not start with \"<?xml\" or \"<VTKFile\"");
  }
}

TEST(VtkData, ZeroAndIsotropicTensorsAreLegalData) {
  auto mesh = hex_mesh(2);
  add_point_tensors(mesh, [](const Vec3& x) { return x.x() < 1.0 ? Sym3{} : Sym3{2, 2, 2, 0, 0, 0}; });
  const fs::path path = write_vtu(mesh, "zero.vtu");
  const VtkData loaded = load(path);
  const Trajectory t = trace_trajectory(*loaded.field, Vec3(0.5, 1, 1), TrajectoryOptions{});
  EXPECT_EQ(t.points.size(), 1u);  // stops at once: no direction there
  EXPECT_EQ(t.forward_stop, StopReason::degenerate);
}

// A hollow cylinder (annulus of hexahedra); a constant tensor whose major
// direction is x would carry a trajectory straight across the hole.
TEST(VtkData, TrajectoryInAHollowCylinderNeverEntersTheHole) {
  const int n_theta = 48, n_r = 3, n_z = 2;
  const double r_in = 0.5, r_out = 1.0;
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto id = [&](int t, int r, int z) { return vtkIdType((t % n_theta) + n_theta * (r + (n_r + 1) * z)); };
  for (int z = 0; z <= n_z; ++z)
    for (int r = 0; r <= n_r; ++r)
      for (int t = 0; t < n_theta; ++t) {
        const double radius = r_in + (r_out - r_in) * r / n_r, angle = 2 * M_PI * t / n_theta;
        points->InsertNextPoint(radius * std::cos(angle), radius * std::sin(angle), 0.5 * z);
      }
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  mesh->SetPoints(points);
  for (int z = 0; z < n_z; ++z)
    for (int r = 0; r < n_r; ++r)
      for (int t = 0; t < n_theta; ++t) {
        const vtkIdType hex[8] = {id(t, r, z),     id(t, r + 1, z),     id(t + 1, r + 1, z),     id(t + 1, r, z),
                                  id(t, r, z + 1), id(t, r + 1, z + 1), id(t + 1, r + 1, z + 1), id(t + 1, r, z + 1)};
        mesh->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      }
  add_point_tensors(mesh, [](const Vec3&) { return Sym3{3, 2, 1, 0, 0, 0}; });
  const fs::path path = write_vtu(mesh, "hollow.vtu");
  const VtkData loaded = load(path);

  TrajectoryOptions options;
  options.step = 0.01;
  const Trajectory t = trace_trajectory(*loaded.field, Vec3(-0.75, 0.1, 0.5), options);
  // The inner wall is a 48-gon inscribed in r = 0.5.
  const double hole = r_in * std::cos(M_PI / n_theta) - 1e-6;
  for (const Vec3& p : t.points) EXPECT_GE(std::hypot(p.x(), p.y()), hole) << p.transpose();
  EXPECT_EQ(t.forward_stop, StopReason::boundary);
  EXPECT_EQ(t.backward_stop, StopReason::boundary);
  // It ends on the walls: one end at the inner wall, one at the outer.
  const double r_front = std::hypot(t.points.front().x(), t.points.front().y());
  const double r_back = std::hypot(t.points.back().x(), t.points.back().y());
  EXPECT_NEAR(std::min(r_front, r_back), r_in, 0.01);
  EXPECT_NEAR(std::max(r_front, r_back), r_out, 0.01);
  // The bounding box alone would have let it run on to x = +1.
  EXPECT_LT(std::max(t.points.front().x(), t.points.back().x()), -0.4);
}

TEST(VtkData, BoundarySurfaceIsTheOuterSkin) {
  auto mesh = hex_mesh(3);
  add_point_tensors(mesh, linear_tensor);
  const fs::path path = write_vtu(mesh, "skin.vtu");
  const VtkData loaded = load(path);
  // 6 faces × 9 quads × 2 triangles, no interior faces.
  EXPECT_EQ(loaded.boundary.triangles.size(), 6u * 9u * 2u);
}

}  // namespace
}  // namespace hsb
