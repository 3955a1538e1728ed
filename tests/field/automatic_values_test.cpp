// The rules for automatic field-side values: lengths from the data's size,
// glyph sizes from its tensors, at any unit scale.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "field/automatic_values.h"

namespace hsb {
namespace {

// Eigenvalues whose largest magnitudes are 1, 2, …, n (in `unit`).
std::vector<Vec3> magnitudes(int n, double unit) {
  std::vector<Vec3> out;
  for (int i = 1; i <= n; ++i) out.push_back(unit * Vec3(0.5 * i, 0.1 * i, -1.0 * i));
  return out;
}

TEST(AutomaticValues, LengthsAreFractionsOfTheDiagonal) {
  const Box3 box{Vec3(0, 0, 0), Vec3(3, 4, 12)};  // diagonal 13
  EXPECT_DOUBLE_EQ(automatic_step(box), 13.0 / 400.0);
  EXPECT_DOUBLE_EQ(automatic_max_length(box), 26.0);
  EXPECT_DOUBLE_EQ(automatic_spacing(box, RadiusMapping::sqrt), 13.0 / 40.0);
  EXPECT_DOUBLE_EQ(automatic_spacing(box, RadiusMapping::normalized), 13.0 / 25.0);
  const SeedSpec seeds = automatic_seeds(box);
  ASSERT_EQ(seeds.grids.size(), 1u);
  EXPECT_EQ(seeds.frame, SeedFrame::bounds);
  EXPECT_EQ(seeds.grids[0].corner, Vec3(0, 0, 0.5));  // across the longest axis, z
}

TEST(AutomaticValues, ReferenceGlyphIsAFiftiethOfTheDiagonalAtTheNinetiethPercentile) {
  const Box3 box{Vec3::Zero(), Vec3(2, 0, 0)};  // D = 2
  const double extent = 0.5;                   // R · level radius
  GlyphSizeSpec spec;
  spec.mapping = RadiusMapping::linear;
  const GlyphMapping m = automatic_glyph_mapping(spec, magnitudes(101, 1.0), box, extent);
  // Largest magnitudes 1 … 101; the 90th percentile is 91.
  EXPECT_NEAR(extent * map_radii(Vec3(91, 0, 0), m).maxCoeff(), 2.0 / 50.0, 1e-12);
  // The ceiling is three such glyphs, the floor a twentieth of one.
  EXPECT_NEAR(m.ceiling, 3.0 * m.scale * 91.0, 1e-12);
  EXPECT_NEAR(m.floor, m.scale * 91.0 / 20.0, 1e-12);
  // A singular point's huge value is clamped, keeping its shape.
  const Vec3 huge = map_radii(Vec3(1e6, 5e5, 0), m);
  EXPECT_NEAR(huge.maxCoeff(), m.ceiling, 1e-12);
  EXPECT_NEAR(huge[1] / huge[0], 0.5, 1e-12);
}

TEST(AutomaticValues, SameGlyphsInAnyUnits) {
  // Metres and pascals against millimetres and megapascals: the glyphs,
  // measured in the data's own length unit, are the same fraction of it.
  const Box3 metres{Vec3::Zero(), Vec3(0.1, 0.04, 0.005)};
  const Box3 millimetres{Vec3::Zero(), Vec3(100, 40, 5)};
  for (RadiusMapping mapping : {RadiusMapping::linear, RadiusMapping::sqrt, RadiusMapping::normalized}) {
    GlyphSizeSpec spec;
    spec.mapping = mapping;
    const GlyphMapping a = automatic_glyph_mapping(spec, magnitudes(50, 2.5e7), metres, 0.5);
    const GlyphMapping b = automatic_glyph_mapping(spec, magnitudes(50, 25.0), millimetres, 0.5);
    const Vec3 l_pa = 2.5e7 * Vec3(30, 4, -11), l_mpa = 25.0 * Vec3(30, 4, -11);
    const Vec3 ra = map_radii(l_pa, a) / metres.diagonal(), rb = map_radii(l_mpa, b) / millimetres.diagonal();
    EXPECT_LT((ra - rb).norm(), 1e-9 * ra.norm()) << int(mapping);
  }
}

TEST(AutomaticValues, FixedSizeMappingsIgnoreMagnitudes) {
  const Box3 box{Vec3::Zero(), Vec3(1, 1, 1)};
  GlyphSizeSpec spec;
  spec.mapping = RadiusMapping::normalized;
  const GlyphMapping m = automatic_glyph_mapping(spec, magnitudes(10, 1e9), box, 0.5);
  EXPECT_NEAR(0.5 * map_radii(Vec3(7, -2, 1), m).maxCoeff(), box.diagonal() / 100.0, 1e-12);
}

TEST(AutomaticValues, PinnedValuesWinAndZerosAreIgnored) {
  const Box3 box{Vec3::Zero(), Vec3(1, 1, 1)};
  GlyphSizeSpec spec;
  spec.mapping = RadiusMapping::linear;
  spec.scale = 0.25;
  spec.floor = 0.01;
  GlyphMapping m = automatic_glyph_mapping(spec, magnitudes(10, 1.0), box, 0.5);
  EXPECT_EQ(m.scale, 0.25);
  EXPECT_EQ(m.floor, 0.01);
  EXPECT_NEAR(m.ceiling, 3.0 * 0.25 * 9.0, 1e-12);  // 90th percentile of 1…10: 9 (nearest rank)
  // All-zero tensors (a data set at rest) give no reference: no division by zero.
  spec = GlyphSizeSpec{};
  m = automatic_glyph_mapping(spec, std::vector<Vec3>(5, Vec3::Zero()), box, 0.5);
  EXPECT_TRUE(std::isfinite(m.scale));
  EXPECT_GT(m.scale, 0.0);
}

}  // namespace
}  // namespace hsb
