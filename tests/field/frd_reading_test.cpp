// CalculiX's .frd results as ccx 2.20 writes them (scenes/data/formats: a
// plate of quadratic tetrahedra, ASCII and binary; a block of quadratic
// hexahedra and wedges in two steps), and small files of the format's
// short layout written here: read with VTK's node order (every cell's
// faces outward, every midside node on its edge), ccx's stress in VTK's
// component order, one step at a time; broken files refused naming the
// line.

#include <gtest/gtest.h>

#include <vtkCell.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "base/vec3.h"
#include "field/reading/component_arrays.h"
#include "field/reading/data_error.h"
#include "field/reading/dataset_reading.h"
#include "field/reading/vtk_data.h"
#include "field/reading/vtk_session.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

const std::string formats = std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/";

vtkSmartPointer<vtkDataSet> read_frd(const std::string& path, int step = -1) {
  const VtkSession vtk;
  return read_dataset(path, vtk, {step});
}

Vec3 point_of(vtkDataSet* data, vtkIdType i) {
  double p[3];
  data->GetPoint(i, p);
  return Vec3(p[0], p[1], p[2]);
}

// The volume VTK's own faces of `cell` enclose (the divergence theorem over
// their corner triangles): positive when they face outward, as VTK's
// geometry filter draws them. (For a wedge this is not the sign of the
// Jacobian of VTK's parametric coordinates, which are its mirror image.)
double face_volume(vtkCell* cell) {
  double volume = 0.0;
  for (int f = 0; f < cell->GetNumberOfFaces(); ++f) {
    vtkCell* face = cell->GetFace(f);
    const int type = face->GetCellType();
    const int corners = type == VTK_TRIANGLE || type == VTK_QUADRATIC_TRIANGLE ? 3 : 4;
    std::array<Vec3, 4> p;
    for (int k = 0; k < corners; ++k) {
      double x[3];
      face->GetPoints()->GetPoint(k, x);
      p[std::size_t(k)] = Vec3(x[0], x[1], x[2]);
    }
    for (int k = 1; k + 1 < corners; ++k) volume += p[0].dot(p[std::size_t(k)].cross(p[std::size_t(k + 1)])) / 6.0;
  }
  return volume;
}

// Every cell faces outward, and each quadratic edge's midside node lies
// within `bend` (of the edge's length) of the middle of its ends.
void expect_cells_right(vtkDataSet* data, double bend) {
  for (vtkIdType i = 0; i < data->GetNumberOfCells(); ++i) {
    vtkCell* cell = data->GetCell(i);
    EXPECT_GT(face_volume(cell), 0.0) << "cell " << i << " of type " << cell->GetCellType() << " is inside out";
    for (int e = 0; e < cell->GetNumberOfEdges(); ++e) {
      vtkCell* edge = cell->GetEdge(e);
      if (edge->GetNumberOfPoints() != 3) continue;
      const Vec3 a = point_of(data, edge->GetPointId(0)), b = point_of(data, edge->GetPointId(1));
      const Vec3 middle = point_of(data, edge->GetPointId(2));
      EXPECT_LE((middle - 0.5 * (a + b)).norm(), bend * (b - a).norm()) << "cell " << i << ", edge " << e;
    }
  }
}

std::map<int, int> cell_types(vtkDataSet* data) {
  std::map<int, int> types;
  for (vtkIdType i = 0; i < data->GetNumberOfCells(); ++i) ++types[data->GetCellType(i)];
  return types;
}

// The point data's tuple of `name` at point `i`.
std::vector<double> tuple_of(vtkDataSet* data, const char* name, vtkIdType i) {
  vtkDataArray* array = data->GetPointData()->GetArray(name);
  EXPECT_TRUE(array) << name;
  if (!array) return {};
  std::vector<double> t(std::size_t(array->GetNumberOfComponents()));
  array->GetTuple(i, t.data());
  return t;
}

void expect_near_all(const std::vector<double>& read, const std::vector<double>& expected, double tolerance,
                     const std::string& what) {
  ASSERT_EQ(read.size(), expected.size()) << what;
  for (std::size_t k = 0; k < read.size(); ++k) EXPECT_NEAR(read[k], expected[k], tolerance) << what << ", component " << k;
}

// The sampled tensor at `x` against ccx's six values there (SXX SYY SZZ SXY SYZ SZX).
void expect_sampled(const VtkData& data, const Vec3& x, const std::vector<double>& ccx, double tolerance) {
  ASSERT_TRUE(data.field);
  const std::optional<Sym3> s = data.field->sample(x);
  ASSERT_TRUE(s) << x.transpose();
  expect_near_all({s->xx, s->yy, s->zz, s->xy, s->yz, s->xz}, ccx, tolerance, "sampled at a node");
}

// Node numbers → STRESS, SXX SYY SZZ SXY SYZ SZX as the file's text has
// them (the plate's nodes are numbered 1 to 2725 in the file's order).
const std::map<int, std::vector<double>> plate_stress{
    {1, {9.97888E+00, -2.90850E-02, -6.12153E-05, 2.93076E-02, 1.48612E-04, 6.71476E-04}},
    {8, {2.94569E+01, 8.69824E-01, 1.15564E-01, -3.08113E-02, -1.41184E-01, 5.10027E-04}},
    {1877, {1.40044E+01, 2.04492E+00, 1.15871E-01, -3.88776E+00, -2.65238E-02, -2.07336E-01}},
    {2725, {9.99450E+00, 1.84871E-01, -4.82733E-04, -9.65839E-02, 1.65269E-03, -1.32630E-03}},
};

TEST(FrdReading, ThePlateIsQuadraticTetrahedraWithCcxsStressInVtksOrder) {
  for (const char* file : {"ccx_plate.frd", "ccx_plate_binary.frd"}) {
    SCOPED_TRACE(file);
    const vtkSmartPointer<vtkDataSet> data = read_frd(formats + file);
    EXPECT_EQ(data->GetNumberOfPoints(), 2725);
    EXPECT_EQ(data->GetNumberOfCells(), 1381);
    EXPECT_EQ(cell_types(data), (std::map<int, int>{{VTK_QUADRATIC_TETRA, 1381}}));
    // The hole's edges are curved: their midside nodes lie on the cylinder.
    expect_cells_right(data, 0.1);
    EXPECT_LT((point_of(data, 1876) - Vec3(-6.50627E-01, -9.93076E-01, 6.64749E-01)).norm(), 1e-5);
    for (const auto& [node, stress] : plate_stress)
      expect_near_all(tuple_of(data, "STRESS", node - 1), stress, 1e-5 * std::fabs(stress[0]), "node " + std::to_string(node));
    ASSERT_TRUE(data->GetPointData()->GetTensors());
    EXPECT_STREQ(data->GetPointData()->GetTensors()->GetName(), "STRESS");
    EXPECT_EQ(recorded_component_order(data, "STRESS"), "CalculiX's STRESS: SXX SYY SZZ SXY SYZ SZX");
    EXPECT_EQ(recorded_component_order(data, "TOSTRAIN"), "CalculiX's TOSTRAIN: EXX EYY EZZ EXY EYZ EZX");
    EXPECT_EQ(tuple_of(data, "TOSTRAIN", 0).size(), 6u);
    EXPECT_EQ(tuple_of(data, "DISP", 0).size(), 3u);  // D1 D2 D3; ALL is not in the file
    EXPECT_FALSE(data->GetPointData()->GetArray("ERROR"));
  }
  EXPECT_TRUE(series_times(formats + "ccx_plate.frd").empty());  // one step
}

TEST(FrdReading, TheBinaryPlateIsTheAsciiOne) {
  const vtkSmartPointer<vtkDataSet> text = read_frd(formats + "ccx_plate.frd");
  const vtkSmartPointer<vtkDataSet> binary = read_frd(formats + "ccx_plate_binary.frd");
  ASSERT_EQ(text->GetNumberOfPoints(), binary->GetNumberOfPoints());
  ASSERT_EQ(text->GetNumberOfCells(), binary->GetNumberOfCells());
  for (vtkIdType i = 0; i < text->GetNumberOfPoints(); ++i)
    ASSERT_LT((point_of(text, i) - point_of(binary, i)).norm(), 1e-5 * (1.0 + point_of(binary, i).norm())) << i;
  for (vtkIdType c = 0; c < text->GetNumberOfCells(); ++c)
    for (int k = 0; k < 10; ++k)
      ASSERT_EQ(text->GetCell(c)->GetPointId(k), binary->GetCell(c)->GetPointId(k)) << c;
  vtkDataArray* a = text->GetPointData()->GetArray("STRESS");
  vtkDataArray* b = binary->GetPointData()->GetArray("STRESS");
  ASSERT_TRUE(a && b);
  const double scale = std::max(std::fabs(a->GetRange(0)[0]), std::fabs(a->GetRange(0)[1]));
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int k = 0; k < 6; ++k) {
      const double x = a->GetComponent(i, k), y = b->GetComponent(i, k);
      ASSERT_LE(std::fabs(x - y), 1e-4 * std::fabs(x) + 1e-6 * scale) << "point " << i << ", component " << k;
    }
}

TEST(FrdReading, ThePlatesStressIsSampledAtItsNodes) {
  const VtkData data = load_vtk_data({formats + "ccx_plate.frd"});
  // 1877 is the midside node of element 1's edge 1-4.
  expect_sampled(data, Vec3(-6.50627E-01, -9.93076E-01, 6.64749E-01), plate_stress.at(1877), 0.01);
  expect_sampled(data, Vec3(9.11061E+00, 2.16209E+00, 5.00000E-01), plate_stress.at(2725), 0.01);
}

// ccx_block.frd: STRESS (SXX SYY SZZ SXY SYZ SZX) of both steps at nodes
// of the block, with their places, as its text has them.
struct BlockNode {
  int number;
  Vec3 place;
  std::vector<double> step1, step2;
};
const std::vector<BlockNode> block_nodes{
    // midside nodes of he20s: a top edge's (1-2-3-4 face's) and an edge between the faces
    {156, {1.0, 0.5, 0.5},
     {-3.39359E+01, -2.23034E+00, -2.49916E+00, 5.15673E-01, 1.86788E-01, -6.52485E+00},
     {1.97397E+01, -2.41059E-01, -3.95346E-01, -2.69004E-01, 4.37320E-01, -6.90520E+00}},
    {103, {1.0, 1.0, 0.25},
     {-5.04140E+01, -4.66095E+00, -2.70818E+00, -2.06017E-12, -1.03667E-13, -2.41695E+00},
     {3.22584E+00, -1.31813E+00, -1.22480E-01, -1.12487E-12, -9.79772E-14, -3.40307E+00}},
    // midside nodes of pe15s: a triangle's edge, an edge between the triangles
    {109, {6.0, 1.0, 0.25},
     {-8.58000E+00, 9.27930E-02, -2.28062E-02, -3.66645E-12, -5.37051E-13, -1.20379E+00},
     {4.14197E+01, 9.26239E-02, -2.27562E-02, -3.23157E-12, -7.46818E-13, -1.20376E+00}},
    {161, {6.0, 0.5, 0.5},
     {-5.83263E+00, -6.61083E-03, -1.52740E-01, 1.91533E-02, -1.14102E-02, -2.40528E+00},
     {4.41669E+01, -6.48366E-03, -1.52659E-01, 1.91239E-02, -1.14211E-02, -2.40526E+00}},
    // the clamp's top edge
    {533, {0.0, 0.0, 2.0},
     {9.43237E+01, 4.04251E+01, 4.04252E+01, 1.57680E+01, -6.23055E-06, -1.05826E+01},
     {1.65914E+02, 7.11071E+01, 7.11073E+01, 2.82081E+01, -1.46852E-06, -2.45481E+01}},
};

TEST(FrdReading, TheBlocksHexahedraAndWedgesAreInVtksOrderInTwoSteps) {
  const std::string path = formats + "ccx_block.frd";
  EXPECT_EQ(series_times(path), (std::vector<double>{1.0, 2.0}));
  for (int step : {0, 1}) {
    SCOPED_TRACE(step);
    const vtkSmartPointer<vtkDataSet> data = read_frd(path, step);
    EXPECT_EQ(data->GetNumberOfPoints(), 617);
    EXPECT_EQ(cell_types(data), (std::map<int, int>{{VTK_QUADRATIC_HEXAHEDRON, 40}, {VTK_QUADRATIC_WEDGE, 80}}));
    expect_cells_right(data, 1e-9);  // straight edges: every midside node in the middle
    for (const BlockNode& n : block_nodes) {
      EXPECT_LT((point_of(data, n.number - 1) - n.place).norm(), 1e-9) << n.number;
      const std::vector<double>& stress = step == 0 ? n.step1 : n.step2;
      expect_near_all(tuple_of(data, "STRESS", n.number - 1), stress, 1e-5 * std::fabs(stress[0]),
                      "node " + std::to_string(n.number));
    }
    // Sampled at the midside nodes, the field is their values: the cells'
    // nodes are where VTK's interpolation expects them.
    VtkFileSpec spec{path};
    spec.step = step;
    const VtkData sampled = load_vtk_data(spec);
    for (const BlockNode& n : block_nodes)
      if (n.number != 533) expect_sampled(sampled, n.place, step == 0 ? n.step1 : n.step2, 0.05);
  }
  try {
    read_frd(path, 2);
    FAIL() << "read a step the file does not have";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("data.step 2 is beyond its 2 result steps"), std::string::npos) << e.what();
  }
}

// ---- Files written here, in the short layout (format 0: five-digit numbers).

std::string e12(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%12.5E", v);
  return text;
}
std::string i5(long long v) {
  char text[32];
  std::snprintf(text, sizeof text, "%5lld", v);
  return text;
}
std::string block_line(const char* key, long long count) {
  char text[96];
  std::snprintf(text, sizeof text, "%s%18s%12lld%37s0", key, "", count, "");
  return text;
}
std::string result_line(int step, double time, long long count) {
  char text[96];
  std::snprintf(text, sizeof text, "  100CL%5d%12.9f%12lld%20s%2d%5d%10s%2d", 100 + step, time, count, "", 0, step, "", 0);
  return text;
}

// Nodes 10, 20, ... 130 (numbers with gaps): a cube [0, 1]³ (he8), two
// wedges (pe6) making [1, 2] × [0, 1]², a tetrahedron (te4) beside them.
const std::map<int, Vec3> small_nodes{
    {10, {0, 0, 0}}, {20, {1, 0, 0}}, {30, {1, 1, 0}}, {40, {0, 1, 0}},  {50, {0, 0, 1}},  {60, {1, 0, 1}},  {70, {1, 1, 1}},
    {80, {0, 1, 1}}, {90, {2, 0, 0}}, {100, {2, 1, 0}}, {110, {2, 0, 1}}, {120, {2, 1, 1}}, {130, {3, 0, 0}}};
// ccx's node lists, as for the input (which ccx accepts: no inverted element).
const std::vector<std::pair<int, std::vector<int>>> small_elements{
    {1, {10, 20, 30, 40, 50, 60, 70, 80}}, {2, {20, 90, 30, 60, 110, 70}}, {2, {90, 100, 30, 110, 120, 70}},
    {3, {90, 130, 100, 110}}};

// SXX SYY SZZ SXY SYZ SZX, affine: the linear cells reproduce it.
std::vector<double> small_stress(const Vec3& x, double scale) {
  return {scale * (1 + x.x()), 2 + x.y(), 3 + x.z(), 0.1 * x.x() + 0.2 * x.y(), 0.3 * x.z() - 0.1 * x.x(),
          0.05 * x.y() + 0.2 * x.z()};
}

// Two steps: STRESS (its components listed SXX SYY SZZ SXY SZX SYZ, each
// record's values four on its line and two on a continuation line), DISP
// and ERROR; the second step has no value for node 120.
std::string small_frd(const std::vector<std::pair<int, std::vector<int>>>& elements) {
  std::string f = "    1C\n    1UUSER\n" + block_line("    2C", long(small_nodes.size())) + "\n";
  for (const auto& [n, x] : small_nodes) f += " -1" + i5(n) + e12(x.x()) + e12(x.y()) + e12(x.z()) + "\n";
  f += " -3\n" + block_line("    3C", long(elements.size())) + "\n";
  int number = 0;
  for (const auto& [type, nodes] : elements) {
    f += " -1" + i5(++number) + i5(type) + i5(0) + i5(1) + "\n -2";
    for (int n : nodes) f += i5(n);
    f += "\n";
  }
  f += " -3\n";
  for (int step : {1, 2}) {
    const double scale = step;
    const long count = long(small_nodes.size()) - (step == 2 ? 1 : 0);
    f += "    1PSTEP                         1           1           1\n" + result_line(step, step, count) +
         "\n -4  STRESS      6    1\n -5  SXX         1    4    1    1\n -5  SYY         1    4    2    2\n"
         " -5  SZZ         1    4    3    3\n -5  SXY         1    4    1    2\n -5  SZX         1    4    3    1\n"
         " -5  SYZ         1    4    2    3\n";
    for (const auto& [n, x] : small_nodes) {
      if (step == 2 && n == 120) continue;
      const std::vector<double> s = small_stress(x, scale);
      f += " -1" + i5(n) + e12(s[0]) + e12(s[1]) + e12(s[2]) + e12(s[3]) + "\n -2     " + e12(s[5]) + e12(s[4]) + "\n";
    }
    f += " -3\n" + result_line(step, step, count) +
         "\n -4  DISP        4    1\n -5  D1          1    2    1    0\n -5  D2          1    2    2    0\n"
         " -5  D3          1    2    3    0\n -5  ALL         1    2    0    0    1ALL\n";
    for (const auto& [n, x] : small_nodes)
      if (step == 1 || n != 120) f += " -1" + i5(n) + e12(0.001 * x.x()) + e12(0.0) + e12(-0.002 * x.z()) + "\n";
    f += " -3\n" + result_line(step, step, count) + "\n -4  ERROR       1    1\n -5  STR(%)      1    1    0    0\n";
    for (const auto& [n, x] : small_nodes)
      if (step == 1 || n != 120) f += " -1" + i5(n) + e12(1.5) + "\n";
    f += " -3\n";
  }
  return f + " 9999\n";
}

std::string written(const std::string& name, const std::string& text) {
  const std::string path = (test_temp_dir("frd") / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(FrdReading, LinearCellsShortNumbersGapsContinuationsAndMissingValues) {
  const std::string path = written("small.frd", small_frd(small_elements));
  EXPECT_EQ(series_times(path), (std::vector<double>{1.0, 2.0}));
  const vtkSmartPointer<vtkDataSet> first = read_frd(path);
  ASSERT_EQ(first->GetNumberOfPoints(), 13);
  EXPECT_EQ(cell_types(first), (std::map<int, int>{{VTK_HEXAHEDRON, 1}, {VTK_WEDGE, 2}, {VTK_TETRA, 1}}));
  expect_cells_right(first, 0.0);
  vtkIdType i = 0;
  for (const auto& [n, x] : small_nodes) {  // the points in the file's order
    EXPECT_LT((point_of(first, i) - x).norm(), 1e-12) << n;
    const std::vector<double> s = small_stress(x, 1.0);
    expect_near_all(tuple_of(first, "STRESS", i), s, 1e-5, "node " + std::to_string(n));
    ++i;
  }
  EXPECT_EQ(tuple_of(first, "DISP", 0).size(), 3u);
  EXPECT_FALSE(first->GetPointData()->GetArray("ERROR"));
  // Inside each cell, the affine field.
  const VtkData data = load_vtk_data({path});
  for (const Vec3& x : {Vec3(0.3, 0.6, 0.2), Vec3(1.7, 0.2, 0.5), Vec3(1.4, 0.8, 0.6), Vec3(2.2, 0.2, 0.2)})
    expect_sampled(data, x, small_stress(x, 1.0), 1e-4);
  // The second step: node 120 has no value (NaN), the others theirs.
  const vtkSmartPointer<vtkDataSet> second = read_frd(path, 1);
  for (double v : tuple_of(second, "STRESS", 11)) EXPECT_TRUE(std::isnan(v));
  expect_near_all(tuple_of(second, "STRESS", 6), small_stress(small_nodes.at(70), 2.0), 1e-5, "node 70, step 2");
}

// The file's lines, and a copy of them with some changed.
std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}
std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& l : lines) text += l + "\n";
  return text;
}
std::size_t line_index(const std::vector<std::string>& lines, const std::string& start) {
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (lines[i].rfind(start, 0) == 0) return i;
  ADD_FAILURE() << "no line begins " << start;
  return 0;
}

// One DataError, whose message holds each of `parts`.
void expect_refused(const std::string& path, const std::vector<std::string>& parts) {
  try {
    read_frd(path);
    FAIL() << path << " was read";
  } catch (const DataError& e) {
    for (const std::string& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(FrdReading, BrokenFilesAreRefusedNamingTheLine) {
  const std::vector<std::string> plate = lines_of(formats + "ccx_plate.frd");
  const std::size_t stress = line_index(plate, " -4  STRESS");

  // Cut short inside a value record of STRESS.
  {
    std::vector<std::string> lines(plate.begin(), plate.begin() + std::ptrdiff_t(stress + 20));
    lines.back() = lines.back().substr(0, 40);
    const std::string path = written("cut.frd", joined(lines));
    expect_refused(path, {path + ":" + std::to_string(stress + 20) + ":", "STRESS"});
  }
  // A record with five of STRESS's six values.
  {
    std::vector<std::string> lines = plate;
    std::string& record = lines[stress + 10];
    record = record.substr(0, record.size() - 12);
    const std::string path = written("five_values.frd", joined(lines));
    expect_refused(path, {path + ":" + std::to_string(stress + 11) + ":", "5 of the 6 values of block STRESS"});
  }
  // A result block declaring more records than it has.
  {
    std::vector<std::string> lines = plate;
    std::string& header = lines[stress - 1];
    header.replace(24, 12, "        2726");
    const std::string path = written("count.frd", joined(lines));
    expect_refused(path, {path + ":", "declares 2726 value records and has 2725"});
  }
  // An element naming a node the node block does not list.
  {
    std::vector<std::string> lines = plate;
    const std::size_t nodes_line = line_index(lines, "    3C") + 2;
    lines[nodes_line].replace(3, 10, "     99999");
    const std::string path = written("no_node.frd", joined(lines));
    expect_refused(path, {path + ":" + std::to_string(nodes_line + 1) + ":", "names node 99999"});
  }
  // The binary plate cut inside STRESS's records.
  {
    std::ifstream in(formats + "ccx_plate_binary.frd", std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    bytes.resize(bytes.find(" -4  STRESS") + 1000);
    const std::string path = written("cut_binary.frd", bytes);
    expect_refused(path, {path + ": at byte ", "the value records of block STRESS"});
  }
  // A 2-D element.
  {
    std::vector<std::pair<int, std::vector<int>>> elements = small_elements;
    elements.push_back({8, {10, 20, 30, 50, 60, 70}});
    const std::string text = small_frd(elements);
    const std::string path = written("triangle.frd", text);
    const std::size_t line = std::size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(text.find(" -1    5    8")), '\n')) + 1;
    expect_refused(path, {path + ":" + std::to_string(line) + ":", "frd element type 8 tr6"});
  }
  // Not a .frd at all, or one that turns into something else.
  expect_refused(written("garbage.frd", std::string("\x93\x01garbage\0\xff", 11)), {"garbage.frd:1: not a CalculiX .frd file"});
  const std::string text_path = written("text.frd", "    1C\n    1UUSER\nhello, world\n");
  expect_refused(text_path, {text_path + ":3: expected a block", "hello, world"});
}

}  // namespace
}  // namespace hsb
