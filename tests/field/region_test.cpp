// [region]: a picture that keeps to where the structure is. A synthetic
// diffusion volume (a fibre bundle in a weakly anisotropic background, as
// white matter in grey) read from a file as a user's would be: with
// region.above, seeds, lines and glyphs at data points stay in the bundle;
// without it the background fills the picture.

#include <gtest/gtest.h>

#include <cmath>

#include "field/glyph_pipeline.h"
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

}  // namespace
}  // namespace hsb
