// Diffusion tensors as the real tools write them, each file given alone
// as a user gives it: MRtrix's dwi2tensor (masked and not), DIPY's two
// layouts and Teem's tend estim, all fitted to one simulated acquisition
// of an oblique, LAS-stored volume (scenes/data/generators/formats/
// dwi_simulation.py). Each layout's frame is read right when every
// bundle's glyphs run along its known direction in world coordinates;
// read in the wrong frame they turn 20° to 58° off. Noise stays noise:
// the major family alone, and the background left out.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "field/glyph_pipeline.h"

namespace hsb {
namespace {

// A straight bundle of the simulation: a point on its axis and its
// direction (world, RAS+ mm), from dwi_simulation.bundle_axes().
struct Bundle {
  Vec3 point, along;
};
const Bundle bundle_a{{3.52769, 2.97231, 22.232283}, Vec3(0.940721, 0.282216, 0.188144).normalized()};
const Bundle bundle_b{{2.47231, -30.97231, 13.767717}, Vec3(0.0, 0.196116, 0.980581).normalized()};
// mm: a bundle is 4 voxels of 2.5 mm in radius, its anisotropy full
// within 2 and falling off beyond; a voxel more holds its blended fringe.
constexpr double core_radius = 5.0, reach = 12.5;

double distance_to_axis(const Bundle& b, const Vec3& p) {
  const Vec3 d = p - b.point;
  return (d - d.dot(b.along) * b.along).norm();
}

struct Measured {
  double median_a = 180, median_b = 180;  // degrees between the glyphs' major axes and the bundle
  std::size_t in_a = 0, in_b = 0, elsewhere = 0;
};

Measured measure(const std::string& file, TensorFrame frame = TensorFrame::automatic) {
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::vtk_file;
  spec.data.file.path = std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/" + file;
  spec.data.file.frame = frame;
  const GlyphScene scene = build_glyph_scene(spec, 0.64);
  EXPECT_EQ(scene.quantity, DataQuantity::diffusion) << file;
  for (const Trajectory& t : scene.trajectories) EXPECT_EQ(t.family, EigenFamily::major) << file;
  std::vector<double> a, b;
  Measured m;
  for (const GlyphSource& s : scene.sources) {
    const Vec3 major = s.axes.col(0);
    const auto angle = [&](const Bundle& bundle) {
      return std::acos(std::min(1.0, std::fabs(major.dot(bundle.along)))) * 180.0 / M_PI;
    };
    if (distance_to_axis(bundle_a, s.centre) < core_radius) a.push_back(angle(bundle_a));
    else if (distance_to_axis(bundle_b, s.centre) < core_radius) b.push_back(angle(bundle_b));
    else if (distance_to_axis(bundle_a, s.centre) > reach && distance_to_axis(bundle_b, s.centre) > reach) ++m.elsewhere;
  }
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v.empty() ? 180.0 : v[v.size() / 2];
  };
  m.in_a = a.size(), m.in_b = b.size();
  m.median_a = median(a), m.median_b = median(b);
  return m;
}

class ToolsDiffusionFile : public ::testing::TestWithParam<const char*> {};

TEST_P(ToolsDiffusionFile, EveryBundleRunsAlongItsWorldDirection) {
  const Measured m = measure(GetParam());
  EXPECT_GE(m.in_a, 20u) << GetParam();
  EXPECT_GE(m.in_b, 20u) << GetParam();
  EXPECT_LT(m.median_a, 5.0) << GetParam();
  EXPECT_LT(m.median_b, 5.0) << GetParam();
  // The glyphs are the bundles', not noise's: next to nothing away from
  // them, in the isotropic tissue or the background.
  EXPECT_LT(m.elsewhere, (m.in_a + m.in_b) / 10) << GetParam() << ": " << m.elsewhere << " elsewhere";
}

// The measure tells frames apart: each file read in another's frame
// turns its bundles well off (20° to 58°, by dwi_simulation.py's own check).
TEST(ToolsDiffusionFiles, ReadInAnotherFrameTheBundlesTurnOff) {
  const Measured dipy_as_world = measure("dwi_dipy_tensors_nifti.nii.gz", TensorFrame::world);
  EXPECT_GT(std::max(dipy_as_world.median_a, dipy_as_world.median_b), 15.0);
  const Measured mrtrix_as_fsl = measure("dwi_mrtrix_dt_masked.nii.gz", TensorFrame::fsl);
  EXPECT_GT(std::max(mrtrix_as_fsl.median_a, mrtrix_as_fsl.median_b), 15.0);
}

INSTANTIATE_TEST_SUITE_P(Tools, ToolsDiffusionFile,
                         ::testing::Values("dwi_mrtrix_dt.mif", "dwi_mrtrix_dt_masked.nii.gz", "dwi_mrtrix_dt_unmasked.nii.gz",
                                           "dwi_dipy_tensors_fsl.nii.gz", "dwi_dipy_tensors_nifti.nii.gz",
                                           "dwi_teem_tensors.nrrd"));

}  // namespace
}  // namespace hsb
