// 2-D results: triangles or quads in an axis plane, with plane tensors of
// 3 or 4 components or full ones of 6, read as a thin slab whose tensors are
// planar; anything else 2-D is refused with a reason.
#include <gtest/gtest.h>

#include <algorithm>

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkGeometryFilter.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "field/automatic_values.h"
#include "field/glyph_pipeline.h"
#include "field/reading/data_error.h"
#include "field/reading/vtk_data.h"
#include "tests/temp_dir.h"
#include "tests/vtk_written.h"

namespace hsb {
namespace {

// An n × n grid of quads (or of triangles, two per quad) spanning [0, 2]
// along the in-plane axes u, v of the plane `axis` = 0.5, with point
// values `array` from `tensor(u, v)`: 3 components (xx, yy, xy), 4 or 6
// (or 2, a vector).
std::string plane_mesh(const std::string& name, int axis, bool triangles, int components,
                       const std::function<std::vector<double>(double, double)>& tensor, double lift_last = 0.0,
                       const char* array = "stress") {
  const int n = 6, u = (axis + 1) % 3, v = (axis + 2) % 3;
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto values = vtkSmartPointer<vtkDoubleArray>::New();
  values->SetName(array);
  values->SetNumberOfComponents(components);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double p[3];
      p[axis] = 0.5, p[u] = 2.0 * i / n, p[v] = 2.0 * j / n;
      points->InsertNextPoint(p);
      values->InsertNextTuple(tensor(p[u], p[v]).data());
    }
  double last[3];
  points->GetPoint(points->GetNumberOfPoints() - 1, last);
  last[axis] += lift_last;  // a surface bent out of its plane
  points->SetPoint(points->GetNumberOfPoints() - 1, last);
  grid->SetPoints(points);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const vtkIdType a = j * (n + 1) + i, b = a + 1, c = b + n + 1, d = a + n + 1;
      if (triangles) {
        const vtkIdType t1[3] = {a, b, c}, t2[3] = {a, d, c};  // the second clockwise: turned when extruded
        grid->InsertNextCell(VTK_TRIANGLE, 3, t1);
        grid->InsertNextCell(VTK_TRIANGLE, 3, t2);
      } else {
        const vtkIdType q[4] = {a, b, c, d};
        grid->InsertNextCell(VTK_QUAD, 4, q);
      }
    }
  grid->GetPointData()->AddArray(values);
  return written_by<vtkXMLUnstructuredGridWriter>(grid, test_temp_dir("plane_data") / name);
}

// Linear in-plane stresses: exact under linear and bilinear interpolation
// along one axis (to the float precision of the written points).
std::vector<double> plane_stress(double u, double v) { return {1 + u, 2 - 0.5 * v, 0.3 * u + 0.1}; }

TEST(PlaneData, PlaneStressOnTrianglesIsReadInItsPlane) {
  const VtkData data = load_vtk_data({plane_mesh("triangles.vtu", 2, true, 3, plane_stress)});
  ASSERT_TRUE(data.field);
  ASSERT_EQ(data.plane_axis, 2);
  for (const Vec3& p : {Vec3(0.3, 0.4, 0.5), Vec3(1.7, 1.1, 0.5), Vec3(1.0, 1.9, 0.5)}) {
    const std::optional<Sym3> s = data.field->sample(p);
    ASSERT_TRUE(s) << p.transpose();
    const std::vector<double> t = plane_stress(p.x(), p.y());
    // The out-of-plane normal is the in-plane mean: λ1 and λ3 the in-plane principal stresses.
    const Sym3 expected{t[0], t[1], 0.5 * (t[0] + t[1]), t[2], 0.0, 0.0};
    EXPECT_LT((s->matrix() - expected.matrix()).norm(), 1e-6) << p.transpose();
  }
  EXPECT_FALSE(data.field->sample(Vec3(1, 1, 3)));  // far off the plane: outside
}

// Four components: a 2×2 matrix row by row (numpy's (n, 2, 2) through
// meshio), or XX YY ZZ XY (Code_Aster, Abaqus), told apart by whether the
// middle two agree; only the second is a guess worth a warning.
TEST(PlaneData, FourComponentsAreAMatrixRowByRowOrXxYyZzXy) {
  const auto read = [](const std::string& file, const std::function<std::vector<double>(double, double)>& tensor) {
    return load_vtk_data({plane_mesh(file, 2, true, 4, tensor)});
  };
  const auto rows = [](double u, double v) {
    const std::vector<double> t = plane_stress(u, v);
    return std::vector<double>{t[0], t[2], t[2], t[1]};
  };
  const auto with_zz = [](double u, double v) {
    const std::vector<double> t = plane_stress(u, v);
    return std::vector<double>{t[0], t[1], 0.3 * (t[0] + t[1]), t[2]};
  };
  for (const bool zz : {false, true}) {
    const VtkData data = zz ? read("with_zz.vtu", with_zz) : read("rows.vtu", rows);
    ASSERT_TRUE(data.field);
    for (const Vec3& p : {Vec3(0.3, 0.4, 0.5), Vec3(1.7, 1.1, 0.5)}) {
      const std::optional<Sym3> s = data.field->sample(p);
      ASSERT_TRUE(s) << p.transpose();
      const std::vector<double> t = plane_stress(p.x(), p.y());
      const Sym3 expected{t[0], t[1], 0.5 * (t[0] + t[1]), t[2], 0.0, 0.0};
      EXPECT_LT((s->matrix() - expected.matrix()).norm(), 1e-6) << (zz ? "XX YY ZZ XY at " : "rows at ") << p.transpose();
    }
    const bool warned = std::any_of(data.warnings.begin(), data.warnings.end(), [](const std::string& w) {
      return w.find("array \"stress\" has four components whose second and third differ: read as XX YY ZZ XY") !=
             std::string::npos;
    });
    EXPECT_EQ(warned, zz);
  }
}

// Two components in a z plane: an in-plane vector (a 2-D flow), drawn as one.
TEST(PlaneData, TwoComponentsAreAPlaneVector) {
  const auto swirl = [](double u, double v) { return std::vector<double>{1.0 - v, u - 1.0}; };
  const VtkData data = load_vtk_data({plane_mesh("velocity.vtu", 2, false, 2, swirl, 0.0, "velocity")});
  ASSERT_TRUE(data.vectors);
  EXPECT_FALSE(data.field);
  const std::optional<Vec3> v = data.vectors->sample(Vec3(0.3, 1.6, 0.5));
  ASSERT_TRUE(v);
  EXPECT_LT((*v - Vec3(1.0 - 1.6, 0.3 - 1.0, 0.0)).norm(), 1e-6);
}

TEST(PlaneData, FullTensorsOnQuadsInAYPlaneLoseTheirOutOfPlaneShear) {
  const auto full = [](double u, double v) { return std::vector<double>{1 + u, 5.0, 2 + v, 0.7, 0.9, 0.4}; };
  const VtkData data = load_vtk_data({plane_mesh("quads.vtu", 1, false, 6, full)});
  ASSERT_EQ(data.plane_axis, 1);
  // u = z, v = x for the y plane: at (x, y, z) = (0.6, 0.5, 1.2) the tensor has xx 1.6 (v = x: 2 + 0.6), ...
  const std::optional<Sym3> s = data.field->sample(Vec3(0.6, 0.5, 1.2));
  ASSERT_TRUE(s);
  const double xx = 1 + 1.2, zz = 2 + 0.6;  // u = z, v = x
  const Sym3 expected{xx, 0.5 * (xx + zz), zz, 0.0, 0.0, 0.4};
  EXPECT_LT((s->matrix() - expected.matrix()).norm(), 1e-6);
}

// Polygonal data (.vtp) in a plane is the same 2-D result; a cloud of
// points carrying tensors has no volume, and its picture is a glyph at
// each point, said in a warning.
TEST(PlaneData, PolygonsInAVtpFileAreAPlaneAndAPointCloudIsAGlyphAtEachPoint) {
  const std::string vtu = plane_mesh("for_vtp.vtu", 2, true, 3, plane_stress);
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(vtu.c_str());
  auto surface = vtkSmartPointer<vtkGeometryFilter>::New();
  surface->SetInputConnection(reader->GetOutputPort());
  surface->Update();
  const std::string vtp = written_by<vtkXMLPolyDataWriter>(surface->GetOutput(), test_temp_dir("plane_data") / "plate.vtp");
  const VtkData data = load_vtk_data({vtp});
  ASSERT_EQ(data.plane_axis, 2);
  ASSERT_TRUE(data.field->sample(Vec3(1.1, 0.7, 0.5)));

  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(surface->GetOutput()->GetPoints());
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i) vertices->InsertNextCell(1, &i);
  cloud->SetVerts(vertices);
  cloud->GetPointData()->AddArray(surface->GetOutput()->GetPointData()->GetArray("stress"));
  const std::string points = written_by<vtkXMLPolyDataWriter>(cloud, test_temp_dir("plane_data") / "cloud.vtp");
  const VtkData read = load_vtk_data({points});
  EXPECT_NE(read.no_volume.find("its " + std::to_string(cloud->GetNumberOfPoints()) + " cells are points or lines"),
            std::string::npos)
      << read.no_volume;
  ASSERT_EQ(read.sites.positions.size(), std::size_t(cloud->GetNumberOfPoints()));
  ASSERT_EQ(read.sites.tensors.size(), read.sites.positions.size());
  EXPECT_FALSE(read.field->sample(read.sites.positions[3]));  // nothing between the points, nor at them
  for (std::size_t i = 0; i < read.sites.positions.size(); i += 7) {
    double p[3];
    cloud->GetPoint(vtkIdType(i), p);
    EXPECT_EQ(read.sites.positions[i], Vec3(p[0], p[1], p[2]));
    const std::vector<double> expected = plane_stress(p[0], p[1]);  // xx, yy, xy
    EXPECT_NEAR(read.sites.tensors[i].xx, expected[0], 1e-6);  // float coordinates
    EXPECT_NEAR(read.sites.tensors[i].yy, expected[1], 1e-6);  // float coordinates
    EXPECT_NEAR(read.sites.tensors[i].xy, expected[2], 1e-6);  // float coordinates
  }

  // The scene names only the file: trajectories are asked for (the
  // default), and a glyph at each point is drawn instead.
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::vtk_file;
  spec.data.file.path = points;
  const GlyphScene scene = build_glyph_scene(spec, 1.0);
  EXPECT_EQ(scene.placement, SourcePlacement::at_data_points);
  EXPECT_EQ(scene.sources.size(), read.sites.positions.size());
  ASSERT_FALSE(scene.warnings.empty());
  EXPECT_NE(scene.warnings.back().find("a glyph at each of its"), std::string::npos) << scene.warnings.back();
  // Sized by the gap between the points, not by the data's size: the
  // 90th-percentile glyph is 0.45 of it across.
  const double gap = site_gap(scene.domain, scene.sources.size());
  std::vector<double> sizes;
  for (const GlyphSource& s : scene.sources) sizes.push_back(s.radii.maxCoeff());
  std::sort(sizes.begin(), sizes.end());
  EXPECT_NEAR(sizes[std::size_t(0.9 * double(sizes.size() - 1) + 0.5)], 0.45 * gap, 0.05 * gap);
}

TEST(PlaneData, SeedsLieInThePlaneAndSurfacesOutOfOnePlaneAreRefused) {
  const SeedSpec seeds = automatic_seeds(Box3{Vec3(0, 0, -0.1), Vec3(2, 4, 0.1)}, 2);
  ASSERT_EQ(seeds.grids.size(), 1u);
  EXPECT_EQ(seeds.grids[0].corner.z(), 0.5);  // the middle of the slab, in bounds fractions
  EXPECT_EQ(seeds.grids[0].edge_u.z(), 0.0);
  EXPECT_EQ(seeds.grids[0].edge_v.z(), 0.0);

  // A surface bent out of its plane (a shell) has no plane to make a slab
  // of: its values stand at its points.
  const std::string bent = plane_mesh("bent.vtu", 2, false, 6, [](double, double) { return std::vector<double>(6, 1.0); }, 0.3);
  const VtkData shell = load_vtk_data({bent});
  EXPECT_FALSE(shell.plane_axis);
  EXPECT_NE(shell.no_volume.find("cells are surfaces not in an axis plane"), std::string::npos) << shell.no_volume;
  EXPECT_FALSE(shell.sites.positions.empty());
}

}  // namespace
}  // namespace hsb
