// MED files (field/reading/med_reading.cpp): Code_Aster's results as the
// committed aster_plate files lay them out (scenes/data/generators/formats/
// med_plate.py), and small files written here by the MED library itself.
// No cell is read inside out, each of MED's cell types comes in VTK's node
// order, Code_Aster's six stress components land in VTK's order by their
// names (XZ and YZ are zero in the plate: the small files tell them apart),
// and files that are no MED are refused naming the file.

#include <gtest/gtest.h>

#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkHexahedron.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPyramid.h>
#include <vtkSmartPointer.h>
#include <vtkTetra.h>
#include <vtkWedge.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "field/reading/component_arrays.h"
#include "field/reading/data_error.h"
#include "field/reading/dataset_reading.h"
#include "field/reading/vtk_data.h"
#include "field/reading/vtk_session.h"
#include "tests/temp_dir.h"

// Last: med.h defines macros of short names.
#include <med.h>

namespace hsb {
namespace {

namespace fs = std::filesystem;

std::string committed(const std::string& name) { return std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/" + name; }

std::string temp_path(const std::string& name) { return (test_temp_dir("med") / name).string(); }

// The grid hsb reads from `path` at `step`, checked as every data set is.
vtkSmartPointer<vtkDataSet> read_grid(const std::string& path, int step = -1) {
  const VtkSession vtk;
  ReadRequest request;
  request.step = step;
  return read_dataset(path, vtk, request);
}

// VTK's own signed volume of a 3-D cell: that of the tetrahedra VTK cuts
// it into (ParaView's Cell Size says the same). Negative: inside out.
double vtk_volume(vtkCell* cell) {
  auto ids = vtkSmartPointer<vtkIdList>::New();
  auto corners = vtkSmartPointer<vtkPoints>::New();
  cell->Triangulate(0, ids, corners);
  double volume = 0;
  for (vtkIdType t = 0; t + 3 < corners->GetNumberOfPoints(); t += 4) {
    double a[3], b[3], c[3], d[3];
    corners->GetPoint(t, a), corners->GetPoint(t + 1, b), corners->GetPoint(t + 2, c), corners->GetPoint(t + 3, d);
    volume += vtkTetra::ComputeVolume(a, b, c, d);
  }
  return volume;
}

// ((p1 − p0) × (p2 − p0)) · (p3 − p0) / 6 of the cell's points a, b, c, d:
// a tetrahedron's volume as VTK orders it (positive when p3 sees p0 p1 p2
// turn counter-clockwise), and for a hexahedron that of its corner at 0.
double corner_volume(vtkCell* cell, int a, int b, int c, int d) {
  double p[4][3];
  cell->GetPoints()->GetPoint(a, p[0]), cell->GetPoints()->GetPoint(b, p[1]);
  cell->GetPoints()->GetPoint(c, p[2]), cell->GetPoints()->GetPoint(d, p[3]);
  return vtkTetra::ComputeVolume(p[0], p[1], p[2], p[3]);
}

vtkIdType nearest_point(vtkDataSet* data, double x, double y, double z) {
  vtkIdType best = -1;
  double closest = HUGE_VAL;
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    if (const double d = std::hypot(p[0] - x, p[1] - y, p[2] - z); d < closest) closest = d, best = i;
  }
  return best;
}

const char* const code_aster_order = "Code_Aster's SIXX SIYY SIZZ SIXY SIXZ SIYZ, by the field's component names";

TEST(MedReading, CodeAsterTetrahedraAreReadInVtkOrder) {
  const vtkSmartPointer<vtkDataSet> grid = read_grid(committed("aster_plate.med"));
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->GetNumberOfPoints(), 462);
  ASSERT_EQ(grid->GetNumberOfCells(), 1381);
  double total = 0;
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i) {
    ASSERT_EQ(grid->GetCellType(i), VTK_TETRA) << i;
    vtkCell* cell = grid->GetCell(i);
    // The file has each of them inside out for VTK, as MED orders a tetrahedron.
    EXPECT_GT(corner_volume(cell, 0, 1, 2, 3), 0.0) << "cell " << i;
    EXPECT_GT(vtk_volume(cell), 0.0) << "cell " << i;
    total += vtk_volume(cell);
  }
  // The plate 20 × 10 × 1 less its hole of radius 1 (faceted: a little less hole).
  EXPECT_NEAR(total, 200.0 - M_PI, 0.1);
}

TEST(MedReading, CodeAsterHexahedraAreReadInVtkOrder) {
  const vtkSmartPointer<vtkDataSet> grid = read_grid(committed("aster_plate_hexa.med"));
  ASSERT_TRUE(grid);
  EXPECT_EQ(grid->GetNumberOfPoints(), 2622);
  ASSERT_EQ(grid->GetNumberOfCells(), 1632);
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i) {
    ASSERT_EQ(grid->GetCellType(i), VTK_HEXAHEDRON) << i;
    vtkCell* cell = grid->GetCell(i);
    EXPECT_GT(corner_volume(cell, 0, 1, 3, 4), 0.0) << "cell " << i;
    EXPECT_GT(vtk_volume(cell), 0.0) << "cell " << i;
  }
  const vtkIdType top = nearest_point(grid, 0, 1, 0.5);
  EXPECT_NEAR(grid->GetPointData()->GetArray("SIGM_NOEU")->GetComponent(top, 0), 30.0, 0.1);
  EXPECT_TRUE(series_times(committed("aster_plate_hexa.med")).empty());  // one step
}

// Kirsch's plate: σxx = 30 at the top of the hole, twice that at the
// second step; the nodal stress is what is drawn, its order recorded.
TEST(MedReading, TheNodalStressIsReadAtEachComputingStep) {
  const std::string path = committed("aster_plate.med");
  EXPECT_EQ(series_times(path), (std::vector<double>{1.0, 2.0}));
  for (const int step : {0, 1}) {
    const vtkSmartPointer<vtkDataSet> grid = read_grid(path, step);
    ASSERT_TRUE(grid);
    vtkDataArray* stress = grid->GetPointData()->GetArray("SIGM_NOEU");
    ASSERT_TRUE(stress);
    ASSERT_EQ(stress->GetNumberOfComponents(), 6);
    EXPECT_EQ(grid->GetPointData()->GetTensors(), stress);
    EXPECT_EQ(recorded_component_order(grid, "SIGM_NOEU"), code_aster_order);
    const vtkIdType top = nearest_point(grid, 0, 1, 0.5);
    EXPECT_NEAR(stress->GetComponent(top, 0), 30.0 * (step + 1), 0.1) << "step " << step;
    EXPECT_NEAR(stress->GetComponent(top, 1), 0.0, 1e-9);
    ASSERT_TRUE(grid->GetPointData()->GetArray("DEPL"));
    EXPECT_EQ(grid->GetPointData()->GetArray("DEPL")->GetNumberOfComponents(), 3);
  }
  // Through the whole reading: drawn, said, and sampled near the hole's top.
  VtkFileSpec spec{path};
  spec.step = 1;
  const VtkData data = load_vtk_data(spec);
  ASSERT_TRUE(data.field);
  const std::optional<Sym3> s = data.field->sample(Vec3(0, 1.02, 0.5));
  ASSERT_TRUE(s);
  EXPECT_GT(s->xx, 50.0);
  EXPECT_LT(s->xx, 62.0);
  const std::string described = describe_vtk_file(spec);
  EXPECT_NE(described.find("tensors   \"SIGM_NOEU\" (6 components, point data)"), std::string::npos) << described;
  EXPECT_NE(described.find(std::string("order     recorded in the file: ") + code_aster_order), std::string::npos)
      << described;
  spec.step = 2;
  try {
    load_vtk_data(spec);
    FAIL() << "step 2 of 2 read";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("data.step 2 is beyond its 2 computing steps (0 to 1)"), std::string::npos)
        << e.what();
  }
}

// SIGM_ELNO holds Kirsch's stress at each cell's nodes: averaged onto the
// points it is the nodal stress again, which it can only be when each
// value lands on the node MED gives it. SIEF_ELGA, one Gauss point a cell,
// is cell data as it is.
TEST(MedReading, PerElementNodeAndGaussPointFieldsAreRead) {
  const vtkSmartPointer<vtkDataSet> grid = read_grid(committed("aster_plate.med"));
  ASSERT_TRUE(grid);
  vtkDataArray* nodal = grid->GetPointData()->GetArray("SIGM_NOEU");
  vtkDataArray* averaged = grid->GetPointData()->GetArray("SIGM_ELNO");
  ASSERT_TRUE(nodal);
  ASSERT_TRUE(averaged);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    for (int c = 0; c < 6; ++c)
      ASSERT_NEAR(averaged->GetComponent(i, c), nodal->GetComponent(i, c), 1e-9) << "point " << i << ", entry " << c;
  EXPECT_NE(recorded_reading_note(grid, "SIGM_ELNO").find("per element node"), std::string::npos);
  EXPECT_EQ(recorded_component_order(grid, "SIGM_ELNO"), code_aster_order);
  vtkDataArray* gauss = grid->GetCellData()->GetArray("SIEF_ELGA");
  ASSERT_TRUE(gauss);
  EXPECT_EQ(gauss->GetNumberOfTuples(), 1381);
  double range[2];
  gauss->GetRange(range, 0);
  EXPECT_NEAR(range[1], 26.1, 0.1);  // Kirsch at the centroids of the cells at the hole's top
  EXPECT_EQ(recorded_reading_note(grid, "SIEF_ELGA"), "");  // one Gauss point a cell: nothing averaged
}

// A MED file written by the MED library as Code_Aster's are: one mesh "m"
// in 3-D, its nodes and cells, and fields on it.
class MedWriter {
 public:
  explicit MedWriter(const std::string& path) : id_(MEDfileOpen(path.c_str(), MED_ACC_CREAT)) {
    EXPECT_GE(id_, 0) << path;
    const std::string axes = padded({"X", "Y", "Z"}), units = padded({"", "", ""});
    EXPECT_GE(MEDmeshCr(id_, "m", 3, 3, MED_UNSTRUCTURED_MESH, "", "", MED_SORT_DTIT, MED_CARTESIAN, axes.c_str(),
                        units.c_str()),
              0);
    EXPECT_GE(MEDfamilyCr(id_, "m", "FAMILLE_ZERO", 0, 0, ""), 0);
  }
  ~MedWriter() { MEDfileClose(id_); }
  MedWriter(const MedWriter&) = delete;
  MedWriter& operator=(const MedWriter&) = delete;

  void nodes(const std::vector<double>& xyz) {
    EXPECT_GE(MEDmeshNodeCoordinateWr(id_, "m", MED_NO_DT, MED_NO_IT, 0.0, MED_FULL_INTERLACE, med_int(xyz.size() / 3),
                                      xyz.data()),
              0);
  }
  // `nodes` 1-based, in MED's order.
  void cells(med_geometry_type type, const std::vector<med_int>& nodes) {
    EXPECT_GE(MEDmeshElementConnectivityWr(id_, "m", MED_NO_DT, MED_NO_IT, 0.0, MED_CELL, type, MED_NODAL,
                                           MED_FULL_INTERLACE, med_int(nodes.size()) / (type % 100), nodes.data()),
              0);
  }
  // Field `name`'s values at step (1, 1), time 1, on `entity` (MED_NODE, or
  // MED_CELL of TETRA4 at the Gauss points of `localization`).
  void field(const std::string& name, const std::vector<std::string>& components, med_entity_type entity,
             med_int entities, const std::vector<double>& values, const char* localization = MED_NO_LOCALIZATION) {
    const std::string names = padded(components), units = padded(std::vector<std::string>(components.size(), "MPa"));
    const med_int count = med_int(components.size());
    EXPECT_GE(MEDfieldCr(id_, name.c_str(), MED_FLOAT64, count, names.c_str(), units.c_str(), "", "m"), 0);
    const med_geometry_type type = entity == MED_NODE ? MED_NONE : MED_TETRA4;
    EXPECT_GE(MEDfieldValueWithProfileWr(id_, name.c_str(), 1, 1, 1.0, entity, type, MED_COMPACT_PFLMODE,
                                         MED_NO_PROFILE, localization, MED_FULL_INTERLACE, MED_ALL_CONSTITUENT,
                                         entities, reinterpret_cast<const unsigned char*>(values.data())),
              0);
  }
  // A TETRA4 rule named `name` of Gauss points at `points` (x y z each).
  void gauss_points(const char* name, const std::vector<double>& points) {
    const std::vector<double> reference{0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0};  // Code_Aster's TETRA4
    const std::vector<double> weights(points.size() / 3, 1.0 / 6.0 / double(points.size() / 3));
    EXPECT_GE(MEDlocalizationWr(id_, name, MED_TETRA4, 3, reference.data(), MED_FULL_INTERLACE, med_int(weights.size()),
                                points.data(), weights.data(), MED_NO_INTERPOLATION, MED_NO_MESH_SUPPORT),
              0);
  }

 private:
  // MED's component and axis names: 16 characters each, blank-padded.
  static std::string padded(const std::vector<std::string>& names) {
    std::string s;
    for (const std::string& n : names) s += n + std::string(MED_SNAME_SIZE - n.size(), ' ');
    return s;
  }
  med_idt id_;
};

// The tetrahedron (0,0,0) (1,0,0) (0,1,0) (0,0,1) as MED orders it:
// VTK's first face turned the other way.
const std::vector<double> tet_nodes{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
const std::vector<med_int> med_tet{1, 3, 2, 4};

// The same tensor at 4 nodes: `six` in a field's component order.
std::vector<double> at_four_nodes(const std::array<double, 6>& six) {
  std::vector<double> v;
  for (int n = 0; n < 4; ++n) v.insert(v.end(), six.begin(), six.end());
  return v;
}

// σxz ≠ σyz: Code_Aster's SIXZ (its fifth) is VTK's sixth, XZ; its SIYZ
// (sixth) VTK's fifth, YZ. The components go by their names, in whatever
// order the file has them.
TEST(MedReading, ShearComponentsGoWhereTheirNamesSay) {
  const std::string path = temp_path("shear.med");
  {
    MedWriter med(path);
    med.nodes(tet_nodes);
    med.cells(MED_TETRA4, med_tet);
    med.field("RESU____SIGM_NOEU", {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"}, MED_NODE, 4,
              at_four_nodes({1, 2, 3, 4, 5, 6}));
    med.field("RESU____SIEF_NOEU", {"SIYZ", "SIXX", "SIXZ", "SIYY", "SIXY", "SIZZ"}, MED_NODE, 4,
              at_four_nodes({6, 1, 5, 2, 4, 3}));
    med.field("RESU____EPSI_NOEU", {"EPXX", "EPYY", "EPZZ", "EPXY"}, MED_NODE, 4,
              std::vector<double>(16, 0.5));
  }
  const vtkSmartPointer<vtkDataSet> grid = read_grid(path);
  ASSERT_TRUE(grid);
  ASSERT_EQ(grid->GetNumberOfCells(), 1);
  EXPECT_GT(vtk_volume(grid->GetCell(0)), 0.0);
  EXPECT_NEAR(vtk_volume(grid->GetCell(0)), 1.0 / 6.0, 1e-12);
  for (const char* name : {"SIGM_NOEU", "SIEF_NOEU"}) {
    vtkDataArray* a = grid->GetPointData()->GetArray(name);
    ASSERT_TRUE(a) << name;
    ASSERT_EQ(a->GetNumberOfComponents(), 6);
    for (vtkIdType i = 0; i < 4; ++i) {
      EXPECT_EQ(a->GetComponent(i, 3), 4.0) << name;  // XY
      EXPECT_EQ(a->GetComponent(i, 4), 6.0) << name;  // YZ: SIYZ
      EXPECT_EQ(a->GetComponent(i, 5), 5.0) << name;  // XZ: SIXZ
    }
  }
  EXPECT_EQ(recorded_component_order(grid, "SIGM_NOEU"), code_aster_order);
  EXPECT_EQ(recorded_component_order(grid, "SIEF_NOEU"),
            "its components SIYZ SIXX SIXZ SIYY SIXY SIZZ, by the field's component names");
  // A plane model's four: the shears out of the plane are zero.
  vtkDataArray* strain = grid->GetPointData()->GetArray("EPSI_NOEU");
  ASSERT_TRUE(strain);
  ASSERT_EQ(strain->GetNumberOfComponents(), 6);
  EXPECT_EQ(strain->GetComponent(0, 3), 0.5);
  EXPECT_EQ(strain->GetComponent(0, 4), 0.0);
  EXPECT_EQ(strain->GetComponent(0, 5), 0.0);
  EXPECT_NE(recorded_component_order(grid, "EPSI_NOEU").find("YZ and XZ absent, taken as zero"), std::string::npos);
  // Sampled: the tensor with σxz = 5 and σyz = 6.
  const VtkData data = load_vtk_data({path});
  ASSERT_TRUE(data.field);
  const std::optional<Sym3> s = data.field->sample(Vec3(0.2, 0.2, 0.2));
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->xz, 5.0, 1e-12);
  EXPECT_NEAR(s->yz, 6.0, 1e-12);
  EXPECT_NEAR(s->xy, 4.0, 1e-12);
}

// A cell's Gauss points are averaged into the cell's one value, and said so.
TEST(MedReading, GaussPointsOfACellAreAveragedAndSaidSo) {
  const std::string path = temp_path("gauss.med");
  {
    MedWriter med(path);
    med.nodes(tet_nodes);
    med.cells(MED_TETRA4, med_tet);
    const double a = 0.1381966011250105, b = 0.5854101966249685;
    med.gauss_points("TE4_FPG4", {a, a, a, b, a, a, a, b, a, a, a, b});
    std::vector<double> values;
    for (const double xx : {10.0, 20.0, 30.0, 40.0}) values.insert(values.end(), {xx, 1, 2, 3, 4, 5});
    med.field("RESU____SIEF_ELGA", {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"}, MED_CELL, 1, values, "TE4_FPG4");
  }
  const vtkSmartPointer<vtkDataSet> grid = read_grid(path);
  ASSERT_TRUE(grid);
  vtkDataArray* gauss = grid->GetCellData()->GetArray("SIEF_ELGA");
  ASSERT_TRUE(gauss);
  EXPECT_EQ(grid->GetCellData()->GetTensors(), gauss);  // no nodal stress: the Gauss points' is drawn
  EXPECT_DOUBLE_EQ(gauss->GetComponent(0, 0), 25.0);
  EXPECT_DOUBLE_EQ(gauss->GetComponent(0, 4), 5.0);  // YZ
  EXPECT_DOUBLE_EQ(gauss->GetComponent(0, 5), 4.0);  // XZ
  EXPECT_NE(recorded_reading_note(grid, "SIEF_ELGA").find("4 Gauss points per cell"), std::string::npos);
  const VtkData data = load_vtk_data({path});
  bool said = false;
  for (const std::string& w : data.warnings) said = said || w.find("4 Gauss points per cell") != std::string::npos;
  EXPECT_TRUE(said);
}

// One cell of each 3-D type MED has and hsb reads, as MED's reference
// elements number them: a first face that turns outward, then the nodes
// on MED's edges in its order of edges (and HEXA27's on its faces, and its
// centre). Each must come out with VTK's positive volume and each node
// where VTK's parametric coordinates put it.
struct MedCell {
  med_geometry_type type;
  int vtk_type;
  double volume;
  std::vector<std::array<double, 3>> corners;
  std::vector<std::vector<int>> between;  // the nodes after the corners: the middle of these corners
};

std::vector<MedCell> med_reference_cells() {
  const std::vector<std::array<double, 3>> tet{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
  const std::vector<std::array<double, 3>> pyramid{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}, {0.5, 0.5, 1}};
  const std::vector<std::array<double, 3>> wedge{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 1}, {1, 0, 1}};
  const std::vector<std::array<double, 3>> hexa{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0},
                                                {0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}};
  const std::vector<std::vector<int>> hexa_edges{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                 {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  std::vector<std::vector<int>> hexa27 = hexa_edges;
  // MED's faces, then the centre.
  for (const std::vector<int>& face : std::vector<std::vector<int>>{{0, 1, 2, 3},
                                                                    {0, 1, 5, 4},
                                                                    {1, 2, 6, 5},
                                                                    {2, 3, 7, 6},
                                                                    {3, 0, 4, 7},
                                                                    {4, 5, 6, 7},
                                                                    {0, 1, 2, 3, 4, 5, 6, 7}})
    hexa27.push_back(face);
  return {
      {MED_TETRA4, VTK_TETRA, 1.0 / 6.0, tet, {}},
      {MED_PYRA5, VTK_PYRAMID, 1.0 / 3.0, pyramid, {}},
      {MED_PENTA6, VTK_WEDGE, 0.5, wedge, {}},
      {MED_HEXA8, VTK_HEXAHEDRON, 1.0, hexa, {}},
      {MED_TETRA10, VTK_QUADRATIC_TETRA, 1.0 / 6.0, tet, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}},
      {MED_PYRA13, VTK_QUADRATIC_PYRAMID, 1.0 / 3.0, pyramid,
       {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}}},
      {MED_PENTA15, VTK_QUADRATIC_WEDGE, 0.5, wedge,
       {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}}},
      {MED_HEXA20, VTK_QUADRATIC_HEXAHEDRON, 1.0, hexa, hexa_edges},
      {MED_HEXA27, VTK_TRIQUADRATIC_HEXAHEDRON, 1.0, hexa, hexa27},
  };
}

// The linear cell of `cell`'s corners (VTK's tetrahedron for a quadratic
// tetrahedron, and so on).
vtkSmartPointer<vtkCell> corner_cell(vtkCell* cell) {
  vtkSmartPointer<vtkCell> linear;
  switch (cell->GetCellType()) {
    case VTK_TETRA:
    case VTK_QUADRATIC_TETRA: linear = vtkSmartPointer<vtkTetra>::New(); break;
    case VTK_PYRAMID:
    case VTK_QUADRATIC_PYRAMID: linear = vtkSmartPointer<vtkPyramid>::New(); break;
    case VTK_WEDGE:
    case VTK_QUADRATIC_WEDGE: linear = vtkSmartPointer<vtkWedge>::New(); break;
    default: linear = vtkSmartPointer<vtkHexahedron>::New();
  }
  for (vtkIdType i = 0; i < linear->GetNumberOfPoints(); ++i) {
    linear->GetPointIds()->SetId(i, i);
    linear->GetPoints()->SetPoint(i, cell->GetPoints()->GetPoint(i));
  }
  return linear;
}

// Where VTK's parametric coordinates of `cell`'s node `k` put it, by the
// cell of its corners.
std::array<double, 3> at_parametric_node(vtkCell* cell, int k) {
  const vtkSmartPointer<vtkCell> linear = corner_cell(cell);
  int sub = 0;
  double x[3], weights[8];
  linear->EvaluateLocation(sub, cell->GetParametricCoords() + 3 * k, x, weights);
  return {x[0], x[1], x[2]};
}

TEST(MedReading, EveryCellTypeComesInVtkOrder) {
  const std::string path = temp_path("cell_types.med");
  const std::vector<MedCell> cells = med_reference_cells();
  {
    MedWriter med(path);
    std::vector<double> xyz;
    std::map<med_geometry_type, std::vector<med_int>> connectivity;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const double shift = 2.0 * double(c);  // apart from each other
      std::vector<std::array<double, 3>> nodes = cells[c].corners;
      for (const std::vector<int>& among : cells[c].between) {
        std::array<double, 3> middle{0, 0, 0};
        for (const int k : among)
          for (std::size_t a = 0; a < 3; ++a) middle[a] += cells[c].corners[std::size_t(k)][a] / double(among.size());
        nodes.push_back(middle);
      }
      for (const std::array<double, 3>& p : nodes) {
        xyz.insert(xyz.end(), {p[0] + shift, p[1], p[2]});
        connectivity[cells[c].type].push_back(med_int(xyz.size() / 3));
      }
    }
    med.nodes(xyz);
    for (const auto& [type, nodes] : connectivity) med.cells(type, nodes);
  }
  const vtkSmartPointer<vtkDataSet> grid = read_grid(path);
  ASSERT_TRUE(grid);
  ASSERT_EQ(grid->GetNumberOfCells(), vtkIdType(cells.size()));
  std::set<int> seen;
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i) {
    vtkCell* cell = grid->GetCell(i);
    const auto expected =
        std::find_if(cells.begin(), cells.end(), [&](const MedCell& m) { return m.vtk_type == cell->GetCellType(); });
    ASSERT_NE(expected, cells.end()) << "VTK type " << cell->GetCellType();
    seen.insert(cell->GetCellType());
    EXPECT_NEAR(vtk_volume(corner_cell(cell)), expected->volume, 1e-12) << cell->GetClassName();
    // VTK 9.1 cuts a triquadratic hexahedron into no tetrahedra, and its
    // quadratic pyramid into too many: their sign is what there is.
    if (cell->GetCellType() != VTK_TRIQUADRATIC_HEXAHEDRON) {
      EXPECT_GT(vtk_volume(cell), 0.0) << cell->GetClassName();
    }
    for (int k = 0; k < cell->GetNumberOfPoints(); ++k) {
      const std::array<double, 3> want = at_parametric_node(cell, k);
      double got[3];
      cell->GetPoints()->GetPoint(k, got);
      EXPECT_NEAR(std::hypot(got[0] - want[0], got[1] - want[1], got[2] - want[2]), 0.0, 1e-12)
          << cell->GetClassName() << " node " << k;
    }
  }
  EXPECT_EQ(seen.size(), cells.size());
}

// A truncated MED file and an HDF5 file that is no MED: one error each,
// naming the file.
TEST(MedReading, FilesThatAreNoMedAreRefusedNamingThem) {
  const std::string truncated = temp_path("truncated.med");
  {
    std::ifstream in(committed("aster_plate.med"), std::ios::binary);
    std::vector<char> head(100000);
    in.read(head.data(), std::streamsize(head.size()));
    std::ofstream(truncated, std::ios::binary).write(head.data(), in.gcount());
  }
  // Exodus II as netCDF-4: HDF5 inside, no MED.
  const std::string other = temp_path("exodus_inside.med");
  fs::copy_file(std::string(HSB_SOURCE_DIR) + "/tests/field/data/meshio_nodal_variables.e", other,
                fs::copy_options::overwrite_existing);
  for (const auto& [path, said] : {std::pair{truncated, "truncated"}, std::pair{other, "no MED file"}}) {
    try {
      load_vtk_data({path});
      FAIL() << path << " read";
    } catch (const DataError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      EXPECT_NE(message.find(said), std::string::npos) << message;
    }
    EXPECT_THROW(series_times(path), DataError);
  }
}

}  // namespace
}  // namespace hsb
