// hsb export: the sources and trajectories as VTK PolyData, read back.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <Eigen/Eigenvalues>
#include <filesystem>
#include <fstream>

#include "renderer/app/export_job.h"
#include "renderer/app/povray_export.h"
#include "renderer/library/prepared_scene.h"
#include "renderer/scene/scene_spec.h"
#include "renderer/surface/glyph_shape.h"
#include "renderer/surface/kernel.h"
#include "tests/renderer/blob_pair.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

vtkSmartPointer<vtkPolyData> read_vtp(const std::string& path) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

// `scene_text` exported from a scene file in a fresh folder `name`: the
// files written, and the glyph scene the export should hold.
struct Exported {
  std::vector<std::string> files;
  GlyphScene expected;
};
Exported export_scene(const std::string& name, const std::string& scene_text) {
  const auto dir = test_temp_dir(name, true);
  const std::string scene = (dir / "s.toml").string();
  std::ofstream(scene) << scene_text;
  Exported e;
  e.files = run_export_job({scene, {}, (dir / "out").string()});
  const SceneSpec spec = load_scene(scene);
  e.expected = build_glyph_scene(spec.pipeline, glyph_extent(spec.surface));
  return e;
}

TEST(Export, SourcesAndTrajectoriesReadBackWithTheirArrays) {
  const auto [files, expected] = export_scene("export_test", "[seeds]\npoints = [[0, 0, 0.5], [0.3, 0.2, 0.6]]\n"
                                                             "[trajectories]\nfamily = \"minor\"\n"
                                                             "[glyphs]\nspacing = 0.2\nmapping = \"normalized\"\nscale = 0.3\n"
                                                             "[surface]\nkernel = \"quartic\"\ninfluence_radius = 1.5\n");
  ASSERT_EQ(files.size(), 2u);

  const auto lines = read_vtp(files[0]);
  EXPECT_EQ(lines->GetNumberOfLines(), 2);
  ASSERT_NE(lines->GetPointData()->GetArray("arc_length"), nullptr);
  EXPECT_NEAR(lines->GetPointData()->GetArray("arc_length")->GetRange()[1],
              std::max(expected.trajectories[0].length(), expected.trajectories[1].length()), 1e-9);

  const auto sources = read_vtp(files[1]);
  ASSERT_EQ(sources->GetNumberOfPoints(), vtkIdType(expected.sources.size()));
  vtkPointData* data = sources->GetPointData();
  for (const char* name : {"tensor", "eigenvalues", "radii", "scalar", "glyph"})
    ASSERT_NE(data->GetArray(name), nullptr) << name;
  ASSERT_NE(data->GetTensors(), nullptr);
  EXPECT_STREQ(data->GetTensors()->GetName(), "glyph");
  EXPECT_EQ(data->GetArray("shape_exponents"), nullptr);  // an ellipsoid has no shape to say
  // The glyph tensor's eigenvalues are 2·R·level(C)·r_k: ParaView's sphere of
  // radius ½ scaled by them is this renderer's isolated ellipsoid.
  const double scale = 2.0 * 1.5 * kernel_level_radius(KernelKind::quartic, 0.5);
  for (vtkIdType i = 0; i < sources->GetNumberOfPoints(); ++i) {
    const GlyphSource& s = expected.sources[std::size_t(i)];
    double g[9], t[9];
    data->GetArray("glyph")->GetTuple(i, g);
    data->GetArray("tensor")->GetTuple(i, t);
    Mat3 gm, tm;
    for (int k = 0; k < 9; ++k) {
      gm(k / 3, k % 3) = g[k];
      tm(k / 3, k % 3) = t[k];
    }
    Vec3 glyph_values = Eigen::SelfAdjointEigenSolver<Mat3>(gm).eigenvalues();
    Vec3 expected_values = scale * s.radii;
    std::sort(expected_values.data(), expected_values.data() + 3);
    EXPECT_LT((glyph_values - expected_values).norm(), 1e-9 * expected_values.norm());
    Vec3 tensor_values = Eigen::SelfAdjointEigenSolver<Mat3>(tm).eigenvalues();
    Vec3 lambdas = s.eigenvalues;
    std::sort(lambdas.data(), lambdas.data() + 3);
    EXPECT_LT((tensor_values - lambdas).norm(), 1e-9 * (1 + lambdas.norm()));
  }
}

// Signed glyphs carry their shape: Kindlmann's exponents for the radii,
// the axis the superquadric is round about, and points on exactly the axes
// whose eigenvalues compress.
TEST(Export, SignedGlyphsCarryTheirShape) {
  const auto [files, expected] =
      export_scene("export_shape_test", "[seeds]\npoints = [[0, 0, 0.5], [0.3, 0.2, 0.6], [0.5, -0.4, -0.2]]\n"
                                        "[trajectories]\nfamily = \"minor\"\n"
                                        "[glyphs]\nspacing = 0.2\nshape = \"signed\"\nsharpness = 2.5\n");
  ASSERT_EQ(files.size(), 2u);
  const auto sources = read_vtp(files[1]);
  ASSERT_EQ(sources->GetNumberOfPoints(), vtkIdType(expected.sources.size()));
  vtkDataArray* exponents = sources->GetPointData()->GetArray("shape_exponents");
  vtkDataArray* axis = sources->GetPointData()->GetArray("shape_axis");
  vtkDataArray* points = sources->GetPointData()->GetArray("shape_points");
  ASSERT_TRUE(exponents && axis && points);
  int tension = 0, compression = 0;
  for (vtkIdType i = 0; i < sources->GetNumberOfPoints(); ++i) {
    const GlyphSource& s = expected.sources[std::size_t(i)];
    const ShapeParams shape = superquadric_params(s.radii, 2.5);
    EXPECT_FLOAT_EQ(float(exponents->GetComponent(i, 0)), shape.alpha);
    EXPECT_FLOAT_EQ(float(exponents->GetComponent(i, 1)), shape.beta);
    EXPECT_EQ(axis->GetComponent(i, 0), double(shape.axis));
    for (int k = 0; k < 3; ++k) {
      const double lambda = s.eigenvalues[k], largest = s.eigenvalues.cwiseAbs().maxCoeff();
      const bool pointed = points->GetComponent(i, k) == 1.0;
      EXPECT_EQ(pointed, lambda < -1e-3 * largest) << "source " << i << " axis " << k << " λ " << lambda;
      (pointed ? compression : tension) += std::fabs(lambda) > 1e-3 * largest;
    }
  }
  EXPECT_GT(tension, 0);  // the point load has both
  EXPECT_GT(compression, 0);
}

// POV-Ray's blob has ellipsoids only: a superquadric scene is refused with
// the key that fixes it, and nothing is written.
TEST(Export, POVRayRefusesSuperquadricsAndWritesNothing) {
  const auto dir = test_temp_dir("export_pov_test", true);
  const std::string scene = (dir / "s.toml").string();
  std::ofstream(scene) << "[seeds]\npoints = [[0, 0, 0.5]]\n"
                          "[glyphs]\nshape = \"superquadric\"\n"
                          "[surface]\nkernel = \"quartic\"\n";
  try {
    run_export_job({scene, {}, (dir / "out").string(), ExportFormat::pov});
    FAIL() << "a superquadric scene was exported to POV-Ray";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("glyphs.shape = \"ellipsoid\""), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "s.pov"));
}

// Two groups (two line families) are two surfaces: POV-Ray gets a blob
// each, so its picture does not blend them either; one group, one blob.
TEST(Export, POVRayWritesABlobPerGroup) {
  const auto dir = test_temp_dir("export_pov_groups", true);
  BlobField field = blob_pair();
  field.kernel = KernelKind::quartic;
  const auto blobs_written = [&](const std::string& name) {
    const std::string pov = (dir / (name + ".pov")).string();
    write_povray_scene(field, CameraSpec{}, ShadingSpec{}, RenderSettings{}, pov, (dir / (name + ".ini")).string(),
                       (dir / (name + ".png")).string());
    std::ifstream in(pov);
    std::string line;
    int blobs = 0, spheres = 0;
    while (std::getline(in, line)) blobs += line.rfind("blob {", 0) == 0, spheres += line.find("sphere {") != std::string::npos;
    EXPECT_EQ(spheres, 2) << name;
    return blobs;
  };
  EXPECT_EQ(blobs_written("one"), 1);
  field.groups = {0, 2};
  EXPECT_EQ(blobs_written("two"), 2);
}

// A full disk (here a file size limit, its signal ignored as hsb does)
// while the POV-Ray scene is written: an error, and neither file left
// behind, where the .pov was left cut short at the limit.
TEST(Export, POVRayOnAFullDiskLeavesNoFile) {
  const auto dir = test_temp_dir("export_pov_full", true);
  BlobField field = blob_pair();
  field.kernel = KernelKind::quartic;
  const pid_t child = fork();
  if (child == 0) {
    signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{200, 200};  // bytes: the .pov's first lines
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
      write_povray_scene(field, CameraSpec{}, ShadingSpec{}, RenderSettings{}, (dir / "full.pov").string(),
                         (dir / "full.ini").string(), (dir / "full.png").string());
    } catch (const std::exception&) {
      _exit(1);
    }
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1) << "the write past the limit was not an error";
  std::string left;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) left += entry.path().filename().string() + " ";
  EXPECT_EQ(left, "");
}

}  // namespace
}  // namespace hsb
