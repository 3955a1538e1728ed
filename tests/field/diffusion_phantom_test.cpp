// The shipped diffusion phantom (scenes/data/formats/dti_fsl_dtifit.nii.gz,
// scenes/data/generators/formats/dti_phantom.py), given alone as a user
// gives it: every one of its bundles is drawn, each along its own
// direction, where a user of an earlier build saw one of the crossing
// bundles missing and the background drawn instead.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>

#include "field/glyph_pipeline.h"
#include "field/tracing/trajectory.h"

namespace hsb {
namespace {

// The phantom's bundles, in world millimetres relative to its centre:
// where each lies, and which way it runs.
struct Bundle {
  const char* name;
  std::function<bool(const Vec3&)> contains;
  std::function<Vec3(const Vec3&)> along;
};

// The arc z = 4 + 12 (x/26)², |x| ≤ 26, in the coronal plane.
double arc_z(double x) { return 4.0 + 12.0 * (x / 26.0) * (x / 26.0); }

TEST(DiffusionPhantom, EveryBundleIsDrawnAlongItsOwnDirection) {
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::vtk_file;
  spec.data.file.path = std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/dti_fsl_dtifit.nii.gz";
  const GlyphScene scene = build_glyph_scene(spec, 0.64);
  EXPECT_EQ(scene.quantity, DataQuantity::diffusion);
  const Vec3 centre(1.5, -17.0, 9.0);
  const std::array<Bundle, 3> bundles{{
      {"the arc (corpus callosum)",
       [](const Vec3& p) {
         return std::fabs(p.x()) <= 28.0 && std::fabs(p.z() - arc_z(p.x())) < 4.0 && p.y() > -24 && p.y() < 16;
       },
       [](const Vec3& p) { return Vec3(1.0, 0.0, 24.0 * p.x() / (26.0 * 26.0)).normalized(); }},
      {"the tracts (corticospinal)",
       [](const Vec3& p) { return std::hypot(std::fabs(p.x()) - 14.0, p.y() + 6.0) < 5.0 && std::fabs(p.z()) < 20.0; },
       [](const Vec3&) { return Vec3(Vec3::UnitZ()); }},
      {"the cingula",
       [](const Vec3& p) { return std::hypot(std::fabs(p.x()) - 6.0, p.z() - 15.0) < 4.0 && std::fabs(p.y()) < 28.0; },
       [](const Vec3&) { return Vec3(Vec3::UnitY()); }},
  }};
  std::size_t background = 0;
  std::array<std::size_t, 3> along{}, across{};
  for (const GlyphSource& s : scene.sources) {
    const Vec3 p = s.centre - centre;
    std::size_t count = 0, which = 0;
    for (std::size_t b = 0; b < bundles.size(); ++b)
      if (bundles[b].contains(p)) ++count, which = b;
    background += count == 0;
    // Where two cross, either direction is right.
    if (count == 1) (std::fabs(s.axes.col(0).dot(bundles[which].along(p))) > 0.8 ? along : across)[which]++;
  }
  for (std::size_t b = 0; b < bundles.size(); ++b) {
    EXPECT_GE(along[b], 10u) << bundles[b].name << " is not drawn along its direction";
    EXPECT_LE(across[b], along[b] / 4) << bundles[b].name << ": " << along[b] << " along, " << across[b] << " across";
  }
  // Near the bundles, yes (their blended fringe); out in the isotropic
  // background, no.
  EXPECT_LT(background, scene.sources.size() / 3) << background << " of " << scene.sources.size();
}

// With FSL's mask of the left hemisphere beside it (region.mask), the
// phantom is drawn on the left (world x below the centre's) alone: its left
// tract and cingulum and the arc's left half, lines stopped at the midline.
TEST(DiffusionPhantom, AMaskFileKeepsThePictureToItsHemisphere) {
  const std::string formats = std::string(HSB_SOURCE_DIR) + "/scenes/data/formats/";
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::vtk_file;
  spec.data.file.path = formats + "dti_fsl_dtifit.nii.gz";
  std::size_t right_unmasked = 0;
  for (const GlyphSource& s : build_glyph_scene(spec, 0.64).sources) right_unmasked += s.centre.x() > 1.5 + 2.0;
  EXPECT_GT(right_unmasked, 50u);  // the right half, unless masked
  spec.region.mask = std::string(HSB_SOURCE_DIR) + "/scenes/data/masks/dti_fsl_left_hemisphere.nii.gz";
  const GlyphScene scene = build_glyph_scene(spec, 0.64);
  ASSERT_FALSE(scene.sources.empty());
  ASSERT_FALSE(scene.trajectories.empty());
  const double midline = 1.5;  // world x of the phantom's centre
  const double voxel = 2.0;    // the mask's edge, interpolated, within a voxel of it
  std::size_t left_tract = 0, left_cingulum = 0;
  for (const GlyphSource& s : scene.sources) {
    EXPECT_LT(s.centre.x(), midline + voxel) << s.centre.transpose();
    left_tract += std::hypot(s.centre.x() - midline + 14.0, s.centre.y() + 17.0 + 6.0) < 5.0;
    left_cingulum += std::hypot(s.centre.x() - midline + 6.0, s.centre.z() - 9.0 - 15.0) < 4.0;
  }
  for (const Trajectory& t : scene.trajectories)
    for (const Vec3& p : t.points) ASSERT_LT(p.x(), midline + voxel) << p.transpose();
  EXPECT_GT(left_tract, 5u);
  EXPECT_GT(left_cingulum, 5u);
}

}  // namespace
}  // namespace hsb
