// Gmsh meshes with post-processing views, read through Gmsh's library:
// the committed plate with a hole (MSH 4.1 and 2.2, written by Gmsh 4.8,
// scenes/data/generators/formats/gmsh_views.py) cell for cell and value for
// value, every element type's node order turned into VTK's, the views'
// steps, and bad files refused as one DataError naming the file.

#include <gtest/gtest.h>

#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCellValidator.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <array>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "field/reading/component_arrays.h"
#include "field/reading/data_error.h"
#include "field/reading/format_reader.h"
#include "field/reading/vtk_data.h"
#include "field/reading/vtk_session.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

const std::string formats = std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/";
const std::string plate_v41 = formats + "gmsh_plate_v41.msh";
const std::string plate_v22 = formats + "gmsh_plate_v22.msh";
// The views' names, as gmsh_views.py gives them.
const char* const node_view = "stress NodeData (Kirsch)";
const char* const element_view = "stress ElementData (Kirsch)";
const char* const element_node_view = "stress ElementNodeData (Kirsch)";

vtkSmartPointer<vtkUnstructuredGrid> read_gmsh(const std::string& path, int step = -1) {
  const VtkSession vtk;
  ReadRequest request;
  request.step = step;
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkUnstructuredGrid::SafeDownCast(gmsh_reader.read(path, request, vtk));
  EXPECT_TRUE(grid) << path;
  return grid;
}

std::string written(const std::string& name, const std::string& text) {
  const std::string path = (test_temp_dir("gmsh") / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Vec3 point(vtkDataSet* data, vtkIdType i) {
  double p[3];
  data->GetPoint(i, p);
  return Vec3(p[0], p[1], p[2]);
}

vtkIdType nearest_point(vtkDataSet* data, const Vec3& to) {
  vtkIdType best = 0;
  for (vtkIdType i = 1; i < data->GetNumberOfPoints(); ++i)
    if ((point(data, i) - to).norm() < (point(data, best) - to).norm()) best = i;
  return best;
}

// The DataError reading `path` gives (through the registry, in a child
// process, as a scene reads it); "" when it reads.
std::string load_error(const std::string& path) {
  try {
    load_vtk_data({path});
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

TEST(GmshReading, PlateReadsItsTetrahedraWithoutTheHoleTriangles) {
  for (const std::string& path : {plate_v41, plate_v22}) {
    const vtkSmartPointer<vtkUnstructuredGrid> grid = read_gmsh(path);
    ASSERT_TRUE(grid);
    EXPECT_EQ(grid->GetNumberOfPoints(), 462) << path;
    ASSERT_EQ(grid->GetNumberOfCells(), 1381) << path;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
      ASSERT_EQ(grid->GetCellType(c), VTK_TETRA) << path << " cell " << c;
      // VTK's orientation: ((p1 − p0) × (p2 − p0)) · (p3 − p0) > 0.
      vtkCell* cell = grid->GetCell(c);
      const Vec3 p0 = point(grid, cell->GetPointId(0));
      const double volume = (point(grid, cell->GetPointId(1)) - p0)
                                .cross(point(grid, cell->GetPointId(2)) - p0)
                                .dot(point(grid, cell->GetPointId(3)) - p0) / 6.0;
      ASSERT_GT(volume, 0.0) << path << " cell " << c;
    }
  }
}

TEST(GmshReading, NodeDataIsKirschsStressAtTheNodes) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_gmsh(plate_v41);
  vtkDataArray* stress = grid->GetPointData()->GetArray(node_view);
  ASSERT_TRUE(stress);
  ASSERT_EQ(stress->GetNumberOfComponents(), 9);
  // 3 × 10 along x at the top of the hole, −10 along y at its side; row by
  // row, symmetric.
  const vtkIdType top = nearest_point(grid, Vec3(0, 1, 0.5));
  EXPECT_LT((point(grid, top).head<2>() - Eigen::Vector2d(0, 1)).norm(), 1e-9);
  EXPECT_NEAR(stress->GetComponent(top, 0), 30.0, 1e-3);
  EXPECT_NEAR(stress->GetComponent(top, 1), stress->GetComponent(top, 3), 1e-12);
  const vtkIdType side = nearest_point(grid, Vec3(1, 0, 0.5));
  EXPECT_NEAR(stress->GetComponent(side, 4), -10.0, 1e-3);
  EXPECT_NEAR(stress->GetComponent(side, 8), 0.0, 1e-12);
}

TEST(GmshReading, BothVersionsGiveTheSameMeshAndValues) {
  const vtkSmartPointer<vtkUnstructuredGrid> v41 = read_gmsh(plate_v41), v22 = read_gmsh(plate_v22);
  ASSERT_EQ(v41->GetNumberOfPoints(), v22->GetNumberOfPoints());
  ASSERT_EQ(v41->GetNumberOfCells(), v22->GetNumberOfCells());
  for (vtkIdType i = 0; i < v41->GetNumberOfPoints(); ++i) ASSERT_EQ(point(v41, i), point(v22, i)) << i;
  for (vtkIdType c = 0; c < v41->GetNumberOfCells(); ++c)
    for (int k = 0; k < 4; ++k) ASSERT_EQ(v41->GetCell(c)->GetPointId(k), v22->GetCell(c)->GetPointId(k)) << c;
  for (const char* name : {node_view, element_node_view, element_view}) {
    vtkDataArray* a = v41->GetPointData()->GetArray(name) ? v41->GetPointData()->GetArray(name) : v41->GetCellData()->GetArray(name);
    vtkDataArray* b = v22->GetPointData()->GetArray(name) ? v22->GetPointData()->GetArray(name) : v22->GetCellData()->GetArray(name);
    ASSERT_TRUE(a && b) << name;
    ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples()) << name;
    for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
      for (int c = 0; c < 9; ++c) ASSERT_EQ(a->GetComponent(t, c), b->GetComponent(t, c)) << name << " " << t;
  }
}

TEST(GmshReading, ElementDataIsCellData) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_gmsh(plate_v22);
  EXPECT_FALSE(grid->GetPointData()->GetArray(element_view));
  vtkDataArray* stress = grid->GetCellData()->GetArray(element_view);
  ASSERT_TRUE(stress);
  ASSERT_EQ(stress->GetNumberOfTuples(), 1381);
  ASSERT_EQ(stress->GetNumberOfComponents(), 9);
  double largest = -1e300;
  for (vtkIdType c = 0; c < 1381; ++c) {
    ASSERT_TRUE(std::isfinite(stress->GetComponent(c, 0))) << c;
    largest = std::max(largest, stress->GetComponent(c, 0));
  }
  // Taken at the centroids: lower than the nodes' 30 (gmsh_views.py: 26.1).
  EXPECT_NEAR(largest, 26.1445, 1e-3);
}

TEST(GmshReading, ElementNodeDataOfAContinuousFieldAveragesToTheNodeData) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_gmsh(plate_v41);
  vtkDataArray* nodes = grid->GetPointData()->GetArray(node_view);
  vtkDataArray* averaged = grid->GetPointData()->GetArray(element_node_view);
  ASSERT_TRUE(nodes && averaged);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    for (int c = 0; c < 9; ++c)
      ASSERT_NEAR(averaged->GetComponent(i, c), nodes->GetComponent(i, c), 1e-12 * 30) << i << " " << c;
}

TEST(GmshReading, ThePlateSamplesAsAField) {
  VtkFileSpec spec{plate_v41};
  spec.array = node_view;
  const VtkData data = load_vtk_data(spec);
  ASSERT_TRUE(data.field);
  // Just inside the body above the top of the hole, where σxx falls from
  // 30 by about 70 per unit of distance.
  const std::optional<Sym3> s = data.field->sample(Vec3(0, 1.002, 0.5));
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->matrix()(0, 0), 30.0, 0.3);
  EXPECT_NEAR(s->matrix()(1, 1), 0.0, 0.5);
}

// ---- Every element type's node order ----

// One element of `gmsh_type` whose nodes stand at Gmsh's reference
// coordinates (`reference`, `dimension` each) mapped by an affine map that
// keeps handedness; node tags 10, 20, ... (gaps); with a NodeData view
// "x" (each node's x) and an ElementNodeData view "x per element" (each
// node's x, in the element's node order).
std::string one_element_file(int gmsh_type, int dimension, const std::vector<double>& reference) {
  const std::size_t n = reference.size() / std::size_t(dimension);
  std::ostringstream text;
  text.precision(17);
  text << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << n << "\n";
  std::vector<double> xs;
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 r = Vec3::Zero();
    for (int d = 0; d < dimension; ++d) r[d] = reference[i * std::size_t(dimension) + std::size_t(d)];
    Mat3 a;
    a << 1.2, 0.3, 0.1, -0.2, 0.9, 0.2, 0.1, -0.1, 1.1;
    const Vec3 x = a * r + Vec3(3, -2, 1);
    xs.push_back(x.x());
    text << 10 * (i + 1) << " " << x.x() << " " << x.y() << " " << x.z() << "\n";
  }
  text << "$EndNodes\n$Elements\n1\n7 " << gmsh_type << " 2 0 1";
  for (std::size_t i = 0; i < n; ++i) text << " " << 10 * (i + 1);
  text << "\n$EndElements\n$NodeData\n1\n\"x\"\n1\n0\n3\n0\n1\n" << n << "\n";
  for (std::size_t i = 0; i < n; ++i) text << 10 * (i + 1) << " " << xs[i] << "\n";
  text << "$EndNodeData\n$ElementNodeData\n1\n\"x per element\"\n1\n0\n3\n0\n1\n1\n7 " << n;
  for (double x : xs) text << " " << x;
  text << "\n$EndElementNodeData\n";
  return written("type" + std::to_string(gmsh_type) + ".msh", text.str());
}

struct ElementCase {
  int gmsh_type, dimension, vtk_type;
  std::vector<double> reference;  // Gmsh's (gmsh::model::mesh::getElementProperties)
};

const std::vector<ElementCase>& element_cases() {
  static const std::vector<ElementCase> cases{
      {2, 2, VTK_TRIANGLE, {0, 0, 1, 0, 0, 1}},
      {3, 2, VTK_QUAD, {-1, -1, 1, -1, 1, 1, -1, 1}},
      {9, 2, VTK_QUADRATIC_TRIANGLE, {0, 0, 1, 0, 0, 1, 0.5, 0, 0.5, 0.5, 0, 0.5}},
      {16, 2, VTK_QUADRATIC_QUAD, {-1, -1, 1, -1, 1, 1, -1, 1, 0, -1, 1, 0, 0, 1, -1, 0}},
      {10, 2, VTK_BIQUADRATIC_QUAD, {-1, -1, 1, -1, 1, 1, -1, 1, 0, -1, 1, 0, 0, 1, -1, 0, 0, 0}},
      {4, 3, VTK_TETRA, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}},
      {5, 3, VTK_HEXAHEDRON, {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1}},
      {6, 3, VTK_WEDGE, {0, 0, -1, 1, 0, -1, 0, 1, -1, 0, 0, 1, 1, 0, 1, 0, 1, 1}},
      {7, 3, VTK_PYRAMID, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 0, 0, 1}},
      {11, 3, VTK_QUADRATIC_TETRA, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5, 0, 0, 0.5, 0.5, 0, 0, 0.5, 0, 0, 0, 0.5, 0,
                                    0.5, 0.5, 0.5, 0, 0.5}},
      {17, 3, VTK_QUADRATIC_HEXAHEDRON, {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1,
                                         1,  -1, 1,  1, 0,  -1, -1, -1, 0,  -1, -1, -1, 0,  1, 0, -1, 1, -1, 0, 0,
                                         1,  -1, 1,  1, 0,  -1, 1,  0, 0,  -1, 1,  -1, 0,  1, 1, 0,  1, 0,  1, 1}},
      {12, 3, VTK_TRIQUADRATIC_HEXAHEDRON,
       {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1, 0,  -1, -1,
        -1, 0,  -1, -1, -1, 0, 1, 0, -1, 1, -1, 0, 0, 1, -1, 1, 1, 0, -1, 1, 0, 0, -1, 1, -1, 0,  1,
        1,  0,  1,  0,  1,  1, 0, 0, -1, 0, -1, 0, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0,  0}},
      {18, 3, VTK_QUADRATIC_WEDGE, {0, 0, -1, 1, 0, -1, 0, 1, -1, 0, 0, 1, 1, 0, 1, 0, 1, 1, 0.5, 0, -1, 0, 0.5, -1, 0, 0, 0,
                                    0.5, 0.5, -1, 1, 0, 0, 0, 1, 0, 0.5, 0, 1, 0, 0.5, 1, 0.5, 0.5, 1}},
      {13, 3, VTK_BIQUADRATIC_QUADRATIC_WEDGE,
       {0, 0, -1, 1, 0, -1, 0, 1, -1, 0, 0, 1, 1, 0, 1, 0, 1, 1, 0.5, 0, -1, 0, 0.5, -1, 0, 0, 0,
        0.5, 0.5, -1, 1, 0, 0, 0, 1, 0, 0.5, 0, 1, 0, 0.5, 1, 0.5, 0.5, 1, 0.5, 0, 0, 0, 0.5, 0, 0.5, 0.5, 0}},
      {19, 3, VTK_QUADRATIC_PYRAMID, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 0, 0, 1, 0, -1, 0, -1, 0, 0, -0.5, -0.5, 0.5, 1,
                                      0, 0, 0.5, -0.5, 0.5, 0, 1, 0, 0.5, 0.5, 0.5, -0.5, 0.5, 0.5}},
      // No VTK cell: read by its corners.
      {14, 3, VTK_PYRAMID, {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 0, 0, 1, 0, -1, 0, -1, 0, 0, -0.5, -0.5, 0.5, 1,
                            0, 0, 0.5, -0.5, 0.5, 0, 1, 0, 0.5, 0.5, 0.5, -0.5, 0.5, 0.5, 0, 0, 0}},
  };
  return cases;
}

// Whether the midside node of each of `cell`'s edges (quadratic cells)
// stands halfway between its ends, and each face's centre node (the
// biquadratic faces) at the mean of its corners: the nodes' places VTK's
// own cell topology gives them.
void expect_nodes_where_vtk_puts_them(vtkDataSet* grid, vtkCell* cell, const std::string& what) {
  for (int e = 0; e < cell->GetNumberOfEdges(); ++e) {
    vtkCell* edge = cell->GetEdge(e);
    if (edge->GetNumberOfPoints() != 3) continue;
    const Vec3 a = point(grid, edge->GetPointId(0)), b = point(grid, edge->GetPointId(1));
    EXPECT_LT((point(grid, edge->GetPointId(2)) - 0.5 * (a + b)).norm(), 1e-12) << what << " edge " << e;
  }
  const auto expect_centre = [&](vtkCell* face, const std::string& which) {
    if (face->GetCellType() != VTK_BIQUADRATIC_QUAD) return;
    Vec3 mean = Vec3::Zero();
    for (int k = 0; k < 4; ++k) mean += 0.25 * point(grid, face->GetPointId(k));
    EXPECT_LT((point(grid, face->GetPointId(8)) - mean).norm(), 1e-12) << what << " " << which;
  };
  expect_centre(cell, "centre");
  for (int f = 0; f < cell->GetNumberOfFaces(); ++f) expect_centre(cell->GetFace(f), "face " + std::to_string(f));
  if (cell->GetCellType() == VTK_TRIQUADRATIC_HEXAHEDRON) {
    Vec3 mean = Vec3::Zero();
    for (int k = 0; k < 8; ++k) mean += 0.125 * point(grid, cell->GetPointId(k));
    EXPECT_LT((point(grid, cell->GetPointId(26)) - mean).norm(), 1e-12) << what << " body centre";
  }
}

TEST(GmshReading, EveryElementTypeTakesVtksNodeOrder) {
  for (const ElementCase& c : element_cases()) {
    const std::string what = "Gmsh type " + std::to_string(c.gmsh_type);
    const vtkSmartPointer<vtkUnstructuredGrid> grid =
        read_gmsh(one_element_file(c.gmsh_type, c.dimension, c.reference));
    ASSERT_TRUE(grid) << what;
    ASSERT_EQ(grid->GetNumberOfCells(), 1) << what;
    ASSERT_EQ(grid->GetCellType(0), c.vtk_type) << what;
    vtkCell* cell = grid->GetCell(0);
    std::set<vtkIdType> distinct;
    for (int k = 0; k < cell->GetNumberOfPoints(); ++k) distinct.insert(cell->GetPointId(k));
    EXPECT_EQ(distinct.size(), std::size_t(cell->GetNumberOfPoints())) << what;
    expect_nodes_where_vtk_puts_them(grid, cell, what);
    // Faces outward and convex, as VTK's own validator sees the cell.
    auto validator = vtkSmartPointer<vtkCellValidator>::New();
    validator->SetInputData(grid);
    validator->Update();
    vtkDataArray* state = vtkDataSet::SafeDownCast(validator->GetOutput())->GetCellData()->GetArray("ValidityState");
    ASSERT_TRUE(state) << what;
    EXPECT_EQ(state->GetComponent(0, 0), 0.0) << what << ": not valid in VTK's eyes";
    // Node tags with gaps find their points; ElementNodeData its nodes.
    vtkDataArray* x = grid->GetPointData()->GetArray("x");
    vtkDataArray* per_element = grid->GetPointData()->GetArray("x per element");
    ASSERT_TRUE(x && per_element) << what;
    for (int k = 0; k < cell->GetNumberOfPoints(); ++k) {
      const vtkIdType p = cell->GetPointId(k);
      EXPECT_DOUBLE_EQ(x->GetComponent(p, 0), point(grid, p).x()) << what << " node " << k;
      EXPECT_DOUBLE_EQ(per_element->GetComponent(p, 0), point(grid, p).x()) << what << " node " << k;
    }
  }
}

// ---- Views ----

// Two tetrahedra sharing the face 2 3 4 (node tags with a gap), and `views`.
std::string two_tets(const std::string& name, const std::string& views) {
  return written(name,
                 "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n9 1 1 1\n"
                 "$EndNodes\n$Elements\n3\n5 2 2 0 1 2 3 4\n7 4 2 0 1 1 2 3 4\n8 4 2 0 1 2 9 3 4\n$EndElements\n" +
                     views);
}

TEST(GmshReading, ElementNodeDataAveragesAtSharedNodes) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid =
      read_gmsh(two_tets("shared.msh",
                         "$ElementNodeData\n1\n\"s\"\n1\n0\n3\n0\n1\n2\n7 4 1 1 1 1\n8 4 3 3 3 3\n$EndElementNodeData\n"));
  ASSERT_EQ(grid->GetNumberOfCells(), 2);  // the triangle is their boundary
  vtkDataArray* s = grid->GetPointData()->GetArray("s");
  ASSERT_TRUE(s);
  const std::array<double, 5> expected{1, 2, 2, 2, 3};  // nodes 1, 2, 3, 4, 9
  for (vtkIdType i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(s->GetComponent(i, 0), expected[std::size_t(i)]) << i;
}

std::string node_step(int index, double time, double value, int components = 1) {
  std::ostringstream text;
  text << "$NodeData\n1\n\"t\"\n1\n" << time << "\n3\n" << index << "\n" << components << "\n5\n";
  for (int node : {1, 2, 3, 4, 9}) {
    text << node;
    for (int c = 0; c < components; ++c) text << " " << value + c;
    text << "\n";
  }
  return text.str() + "$EndNodeData\n";
}

TEST(GmshReading, TimeStepsAreTheStepsThatHoldData) {
  // Steps 0, 1 and 3 (Gmsh keeps 2, empty), and a view of one step.
  const std::string path = two_tets("steps.msh", node_step(0, 0.5, 10) + node_step(1, 1.0, 11) + node_step(3, 2.0, 13) +
                                                     "$ElementData\n1\n\"e\"\n1\n7\n3\n0\n1\n2\n7 5\n8 6\n$EndElementData\n");
  EXPECT_EQ(gmsh_reader.times(path), (std::vector<double>{0.5, 1.0, 2.0}));
  for (const auto& [step, value] : std::vector<std::pair<int, double>>{{-1, 10}, {0, 10}, {1, 11}, {2, 13}}) {
    const vtkSmartPointer<vtkUnstructuredGrid> grid = read_gmsh(path, step);
    ASSERT_TRUE(grid->GetPointData()->GetArray("t")) << step;
    EXPECT_EQ(grid->GetPointData()->GetArray("t")->GetComponent(0, 0), value) << step;
    ASSERT_TRUE(grid->GetCellData()->GetArray("e")) << step;
    EXPECT_EQ(grid->GetCellData()->GetArray("e")->GetComponent(1, 0), 6.0) << step;
  }
  try {
    read_gmsh(path, 3);
    ADD_FAILURE() << "step 3 read";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("data.step 3 is beyond its 3 time steps"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(gmsh_reader.times(plate_v41).empty());
}

TEST(GmshReading, SixComponentsReadInVtksOrderAsARecordedDefault) {
  const vtkSmartPointer<vtkUnstructuredGrid> grid = read_gmsh(two_tets("six.msh", node_step(0, 0, 1, 6)));
  vtkDataArray* t = grid->GetPointData()->GetArray("t");
  ASSERT_TRUE(t);
  ASSERT_EQ(t->GetNumberOfComponents(), 6);
  EXPECT_EQ(t->GetComponent(0, 5), 6.0);
  EXPECT_EQ(recorded_default_order(grid, "t").order, "vtk");
  EXPECT_NE(recorded_default_order(grid, "t").why.find("Gmsh"), std::string::npos);
}

// ---- Bad files ----

void expect_one_error_naming(const std::string& path, const std::string& says) {
  const std::string error = load_error(path);
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_NE(error.find(says), std::string::npos) << error;
}

TEST(GmshReading, TruncatedFilesAreRefused) {
  for (const std::string& plate : {plate_v41, plate_v22}) {
    const std::string text = file_text(plate);
    const std::size_t view = text.find("$ElementData"), view_end = text.find("$EndElementData");
    ASSERT_NE(view_end, std::string::npos) << plate;
    // In its nodes (Gmsh finds it out); just after a view's header, whose
    // count of values the bytes left cannot hold; halfway through the view.
    for (const auto& [at, says] : std::vector<std::pair<std::size_t, std::string>>{
             {20000, "Gmsh cannot read it"},
             {view + 200, "$ElementData section at byte"},
             {(view + view_end) / 2, "Gmsh cannot read it: Could not read data"}}) {
      const std::string path =
          written("cut_" + std::to_string(at) + "_" + std::filesystem::path(plate).filename().string(), text.substr(0, at));
      expect_one_error_naming(path, says);
      EXPECT_THROW(read_gmsh(path), DataError) << path;
    }
  }
  // Gmsh's state, left half-way by the errors, is reset for the next file.
  EXPECT_EQ(read_gmsh(plate_v41)->GetNumberOfCells(), 1381);
}

TEST(GmshReading, FilesThatAreNotGmshMeshesAreRefusedBeforeGmshParsesThem) {
  // Gmsh would parse anything else as a .geo script, which can run commands.
  for (const std::string& text : {std::string("hello, not a mesh\n"), std::string("Point(1) = {0, 0, 0};\n"),
                                  std::string()}) {
    const std::string path = written("not_gmsh.msh", text);
    EXPECT_NE(load_error(path).find(path), std::string::npos) << text;
    try {
      read_gmsh(path);
      ADD_FAILURE() << text;
    } catch (const DataError& e) {
      EXPECT_NE(std::string(e.what()).find("does not begin with $MeshFormat"), std::string::npos) << e.what();
    }
  }
}

TEST(GmshReading, CountsGmshWouldAllocateAreCheckedFirst) {
  // A time step index Gmsh would allocate a billion steps for, and more
  // values than the file has bytes.
  const std::string steps = two_tets("huge_step.msh", node_step(1000000000, 0, 1));
  EXPECT_THROW(read_gmsh(steps), DataError);
  expect_one_error_naming(steps, "time step index 1000000000");
  const std::string values =
      two_tets("huge_count.msh", "$NodeData\n1\n\"t\"\n1\n0\n3\n0\n9\n1000000000\n1 1 2 3 4 5 6 7 8 9\n$EndNodeData\n");
  expect_one_error_naming(values, "1000000000 entities of 9 components");
}

TEST(GmshReading, ValuesForNodesTheMeshLacksAreRefused) {
  const std::string path = two_tets("stray.msh", "$NodeData\n1\n\"t\"\n1\n0\n3\n0\n1\n1\n5 1\n$EndNodeData\n");
  try {
    read_gmsh(path);
    ADD_FAILURE() << "read";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("node 5, which the mesh does not have"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hsb
