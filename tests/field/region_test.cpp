// [region]: a picture that keeps to where the structure is. A synthetic
// diffusion volume (a fibre bundle in a weakly anisotropic background, as
// white matter in grey) read from a file as a user's would be: with
// region.above, seeds, lines and glyphs at data points stay in the bundle;
// without it the background fills the picture.

#include <gtest/gtest.h>

#include <cmath>

#include "field/glyph_pipeline.h"
#include "field/reading/data_error.h"
#include "field/tensor/eigensystem.h"
#include "field/tensor/tensor_measures.h"
#include "tests/temp_dir.h"
#include "tests/vtk_written.h"

namespace hsb {
namespace {

constexpr double kExtent = 0.64;  // an isolated glyph's extent, as in default_features_test.cpp
constexpr double kBundle = 0.12;  // the bundle's radius about the line y = z = 0.5

double from_axis(const Vec3& p) { return std::hypot(p.y() - 0.5, p.z() - 0.5); }

// Diffusion in mm²/s: along the bundle (1.7, 0.3, 0.3)·10⁻³, FA 0.8;
// around it 0.8·10⁻³ with a tenth as much along a direction that turns
// from point to point (FA about 0.08), blended over the bundle's edge.
std::optional<Sym3> fibre_in_background(const Vec3& p) {
  const double w = std::exp(-std::pow(from_axis(p) / kBundle, 4.0));
  const Vec3 n = Vec3(std::sin(37.0 * p.x() + 11.0 * p.z()), std::cos(23.0 * p.y()), std::sin(29.0 * p.z() + 3.0))
                     .normalized();
  const Mat3 background = 0.8e-3 * Mat3::Identity() + 0.1e-3 * n * n.transpose();
  const Mat3 fibre = Vec3(1.7e-3, 0.3e-3, 0.3e-3).asDiagonal();
  return Sym3::symmetric_part(w * fibre + (1.0 - w) * background);
}

std::string volume() {
  static const std::string path =
      grid_written(test_temp_dir("region") / "fibre.vti", {Vec3::Zero(), Vec3::Ones()}, {31, 31, 31},
                   fibre_in_background, "tensors");
  return path;
}

GlyphPipelineSpec spec_for(std::optional<double> above) {
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::vtk_file;
  spec.data.file.path = volume();
  spec.region.above = above;
  return spec;
}

// FA where the pipeline sees it: the grid interpolated, as it samples it.
double fa_in(const LoadedField& data, const Vec3& p) {
  return fractional_anisotropy(decompose(*data.field->sample(p)).values);
}

TEST(Region, LinesSeedsAndGlyphsStayInTheFibre) {
  const GlyphPipelineSpec spec = spec_for(0.3);
  const GlyphScene scene = build_glyph_scene(spec, kExtent);
  const LoadedField data = make_field(spec.data);
  ASSERT_FALSE(scene.sources.empty());
  ASSERT_FALSE(scene.trajectories.empty());
  ASSERT_TRUE(scene.values.region.above);
  EXPECT_EQ(*scene.values.region.above, 0.3);
  for (const Vec3& seed : scene.values.seeds.points) EXPECT_GE(fa_in(data, seed), 0.3) << seed.transpose();
  for (const Trajectory& t : scene.trajectories)
    for (const Vec3& p : t.points) ASSERT_GE(fa_in(data, p), 0.3) << p.transpose();
  // A glyph between two points of a line samples the grid there, which can
  // dip a little below where the points stood.
  for (const GlyphSource& s : scene.sources) {
    EXPECT_GE(fractional_anisotropy(s.eigenvalues), 0.27) << s.centre.transpose();
    EXPECT_LT(from_axis(s.centre), 1.5 * kBundle) << s.centre.transpose();
  }
  // The bundle runs along x: so do its lines, end to end of the volume.
  double longest = 0.0;
  for (const Trajectory& t : scene.trajectories) longest = std::max(longest, t.length());
  EXPECT_GT(longest, 0.9);
}

// Given alone, the file is recognised as diffusion: the region is FA ≥ 0.3,
// the colour the fibres' direction, and the lines as dense in a faint bundle as a strong one.
TEST(Region, DiffusionDataKeepsToItsFibresUnasked) {
  const GlyphScene scene = build_glyph_scene(spec_for(std::nullopt), kExtent);
  EXPECT_EQ(scene.quantity, DataQuantity::diffusion);
  ASSERT_TRUE(scene.values.region.above);
  EXPECT_EQ(*scene.values.region.above, 0.3);
  EXPECT_EQ(scene.values.region.measure, ColorScalar::fa);
  EXPECT_EQ(scene.color, ColorScalar::direction);
  EXPECT_FALSE(*scene.values.seeds.importance);
  ASSERT_FALSE(scene.sources.empty());
  for (const GlyphSource& s : scene.sources) EXPECT_LT(from_axis(s.centre), 1.5 * kBundle);
}

TEST(Region, WithoutOneTheBackgroundFillsThePicture) {
  GlyphPipelineSpec spec = spec_for(std::nullopt);
  spec.data.quantity = DataQuantity::stress;  // read as stress: no region, unless asked
  const GlyphScene scene = build_glyph_scene(spec, kExtent);
  EXPECT_FALSE(scene.values.region.above);
  std::size_t outside = 0;
  for (const GlyphSource& s : scene.sources) outside += from_axis(s.centre) > 2.0 * kBundle;
  EXPECT_GT(outside, scene.sources.size() / 2);
}

TEST(Region, GlyphsAtDataPointsOnlyInsideIt) {
  GlyphPipelineSpec spec = spec_for(0.3);
  spec.placement = SourcePlacement::at_data_points;
  spec.stride = 1;
  const GlyphScene inside = build_glyph_scene(spec, kExtent);
  ASSERT_FALSE(inside.sources.empty());
  for (const GlyphSource& s : inside.sources) EXPECT_GE(fractional_anisotropy(s.eigenvalues), 0.3);
  // The automatic stride thins what the region keeps (fewer than 20,000
  // here: none), not every point of the volume (29,791: every other).
  spec.stride.reset();
  const GlyphScene automatic = build_glyph_scene(spec, kExtent);
  EXPECT_EQ(automatic.values.stride, 1);
  EXPECT_EQ(automatic.sources.size(), inside.sources.size());
  spec.stride = 1;
  spec.region.above = 0.0;  // FA ≥ 0: everywhere
  const GlyphScene all = build_glyph_scene(spec, kExtent);
  EXPECT_EQ(all.sources.size(), 31u * 31u * 31u);
  EXPECT_LT(inside.sources.size(), all.sources.size() / 10);
}

// Seeds in the core, lines followed out through the fringe.
TEST(Region, LinesRunOnToALowerStoppingThreshold) {
  GlyphPipelineSpec spec = spec_for(0.6);
  spec.trajectory.stop_below = 0.3;
  const GlyphScene scene = build_glyph_scene(spec, kExtent);
  const LoadedField data = make_field(spec.data);
  ASSERT_FALSE(scene.trajectories.empty());
  for (const Vec3& seed : scene.values.seeds.points) EXPECT_GE(fa_in(data, seed), 0.6);
  double lowest = 1.0;
  for (const Trajectory& t : scene.trajectories)
    for (const Vec3& p : t.points) {
      ASSERT_GE(fa_in(data, p), 0.3) << p.transpose();
      lowest = std::min(lowest, fa_in(data, p));
    }
  EXPECT_LT(lowest, 0.6);  // out of the core
  EXPECT_EQ(scene.values.trajectory.min_measure, 0.3);
}

TEST(Region, AnotherMeasureAndExplicitSeeds) {
  GlyphPipelineSpec spec = spec_for(0.5);
  spec.region.measure = ColorScalar::westin_linear;
  spec.seeds.points = {Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.9, 0.9)};  // in the bundle, and out of it
  const GlyphScene scene = build_glyph_scene(spec, kExtent);
  const LoadedField data = make_field(spec.data);
  ASSERT_EQ(scene.trajectories.size(), 1u);  // the seed outside has no line
  for (const Vec3& p : scene.trajectories.front().points)
    EXPECT_GE(westin_measures(decompose(*data.field->sample(p)).values).linear, 0.5);
}

// A region of interest: the half x < ½ of the volume, as a scalar array of
// the data file and as a file of its own on the same grid (a brain mask
// beside FSL's tensors). Interpolated, the mask is ½ half a node spacing
// before x = ½: the nodes at 14/30 are in, at 15/30 out.
constexpr double kMaskEdge = 14.5 / 30.0;
double left_half(const Vec3& p) { return p.x() < 0.5 ? 1.0 : 0.0; }

std::string volume_with_mask_array() {
  static const std::string path =
      grid_written(test_temp_dir("region") / "fibre_roi.vti", {Vec3::Zero(), Vec3::Ones()}, {31, 31, 31},
                   fibre_in_background, "tensors", {{"roi", left_half}});
  return path;
}

std::string mask_file() {
  static const std::string path =
      grid_written(test_temp_dir("region") / "roi_mask.vti", {Vec3::Zero(), Vec3::Ones()}, {31, 31, 31}, {}, "",
                   {{"mask", left_half}});
  return path;
}

GlyphPipelineSpec masked_by_array() {
  GlyphPipelineSpec spec = spec_for(0.3);
  spec.data.file.path = volume_with_mask_array();
  spec.data.file.mask_array = "roi";
  spec.region.mask = "array:roi";
  return spec;
}

GlyphPipelineSpec masked_by_file() {
  GlyphPipelineSpec spec = spec_for(0.3);
  spec.region.mask = mask_file();
  return spec;
}

TEST(Region, AMaskKeepsLinesAndGlyphsToItsHalfOfTheFibre) {
  for (const GlyphPipelineSpec& spec : {masked_by_array(), masked_by_file()}) {
    SCOPED_TRACE(spec.region.mask);
    const GlyphScene scene = build_glyph_scene(spec, kExtent);
    ASSERT_FALSE(scene.trajectories.empty());
    ASSERT_TRUE(scene.values.region.mask_field);
    double longest = 0.0;
    int at_mask_edge = 0;
    for (const Trajectory& t : scene.trajectories) {
      longest = std::max(longest, t.length());
      at_mask_edge += t.forward_stop == StopReason::left_region || t.backward_stop == StopReason::left_region;
      for (const Vec3& p : t.points) {
        ASSERT_LE(p.x(), kMaskEdge + 1e-6) << p.transpose();
        ASSERT_LT(from_axis(p), 1.5 * kBundle) << p.transpose();  // and still in the fibre (FA ≥ 0.3)
      }
    }
    // The bundle's lines run from the volume's end up to the mask's edge.
    EXPECT_GT(longest, 0.9 * kMaskEdge);
    EXPECT_GT(at_mask_edge, 0);
    for (const GlyphSource& s : scene.sources) EXPECT_LE(s.centre.x(), kMaskEdge + 1e-6) << s.centre.transpose();
  }
}

TEST(Region, AMaskKeepsAGlyphFieldToItsVoxels) {
  GlyphPipelineSpec unmasked = spec_for(0.3);
  unmasked.placement = SourcePlacement::at_data_points;
  unmasked.stride = 1;
  const std::size_t whole = build_glyph_scene(unmasked, kExtent).sources.size();
  for (GlyphPipelineSpec spec : {masked_by_array(), masked_by_file()}) {
    SCOPED_TRACE(spec.region.mask);
    spec.placement = SourcePlacement::at_data_points;
    spec.stride = 1;
    const GlyphScene scene = build_glyph_scene(spec, kExtent);
    ASSERT_FALSE(scene.sources.empty());
    for (const GlyphSource& s : scene.sources) {
      EXPECT_LT(s.centre.x(), 0.5) << s.centre.transpose();
      EXPECT_GE(fractional_anisotropy(s.eigenvalues), 0.3);
    }
    // The fibre's voxels at x = 0 … 14/30 of the 31 along it.
    EXPECT_EQ(scene.sources.size() * 31, whole * 15);
  }
  // The mask alone (no threshold): every voxel of the half.
  GlyphPipelineSpec alone = masked_by_file();
  alone.region.above.reset();
  alone.data.quantity = DataQuantity::stress;  // no automatic FA threshold either
  alone.placement = SourcePlacement::at_data_points;
  alone.stride = 1;
  EXPECT_EQ(build_glyph_scene(alone, kExtent).sources.size(), 15u * 31u * 31u);
}

TEST(Region, AMaskThatIsNoneIsSaidSo) {
  GlyphPipelineSpec spec = masked_by_array();
  spec.data.file.mask_array = "nope";
  spec.region.mask = "array:nope";
  try {
    build_glyph_scene(spec, kExtent);
    FAIL() << "an array that is not there";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("no array named \"nope\" for region.mask; the file has"), std::string::npos)
        << e.what();
  }
  spec = spec_for(0.3);
  spec.region.mask = volume();  // tensors, no scalar array
  try {
    build_glyph_scene(spec, kExtent);
    FAIL() << "a file with no scalar array";
  } catch (const DataError& e) {
    EXPECT_NE(std::string(e.what()).find("a mask needs one scalar array"), std::string::npos) << e.what();
  }
}


// The threshold decided from the tensor's components (surely_below,
// surely_above) never disagrees with the eigenvalues' FA, and leaves
// holds() only a thin band about the threshold: tensors made with FA
// just under, at and just over it, and far from it on either side.
TEST(Region, ComponentsDecideTheThresholdAsTheEigenvaluesDo) {
  RegionSpec region;
  region.above = 0.3;
  int undecided = 0, tensors = 0;
  for (double offset : {-0.2, -1e-6, -1e-12, 0.0, 1e-12, 1e-6, 0.2})
    for (int turn = 0; turn < 20; ++turn) {
      // Eigenvalues (1 + 2a, 1 − a, 1 − a) have FA 3|a| / √(3 + 6a²)
      // (solved here for a), in a frame turned by `turn`.
      const double fa = 0.3 + offset;
      const double a = fa / std::sqrt(3.0 - 2.0 * fa * fa);
      const Vec3 axis = Vec3(std::sin(turn * 1.3), std::cos(turn * 0.7), 0.4 + 0.1 * turn).normalized();
      const Mat3 r = Eigen::AngleAxisd(0.37 * turn, axis).toRotationMatrix();
      const Sym3 t = Sym3::symmetric_part(r * Vec3(1.0 + 2.0 * a, 1.0 - a, 1.0 - a).asDiagonal() * r.transpose());
      const bool holds = region.holds(Vec3::Zero(), eigenvalues(t));
      ++tensors;
      if (region.surely_below(t)) {
        EXPECT_FALSE(holds) << fa;
      } else if (region.surely_above(t)) {
        EXPECT_TRUE(holds) << fa;
      } else {
        ++undecided;
      }
      if (std::fabs(offset) > 1e-6) {
        EXPECT_TRUE(region.surely_below(t) || region.surely_above(t)) << fa;
      }
    }
  EXPECT_LT(undecided, tensors / 2);
}

}  // namespace
}  // namespace hsb
