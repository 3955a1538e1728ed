// Sources along trajectories: placement by arc length, eigenvalue → radius
// mappings, orientation, colour scalars, and the whole pipeline.

#include "field/glyphs/glyph_sources.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <random>

#include "field/glyph_pipeline.h"
#include "field/sampling/uniform_grid.h"

namespace hsb {
namespace {

struct ConstantField final : TensorField {
  Box3 box{Vec3(-10, -10, -10), Vec3(10, 10, 10)};
  Sym3 value{3, 2, 1, 0, 0, 0};
  Box3 bounds() const override { return box; }
  std::optional<Sym3> sample(const Vec3& x) const override {
    if (!box.contains(x)) return std::nullopt;
    return value;
  }
};

Trajectory polyline(std::vector<Vec3> points) {
  Trajectory t;
  t.points = std::move(points);
  return t;
}

std::vector<Vec3> centres(const std::vector<GlyphSource>& sources) {
  std::vector<Vec3> c;
  for (const GlyphSource& s : sources) c.push_back(s.centre);
  return c;
}

// Eigenvalues 4 ≥ 0.25 ≥ −1 along the columns of a fixed rotation.
const Vec3 kValues(4.0, 0.25, -1.0);
Mat3 test_rotation() {
  return Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
}
Sym3 test_tensor() {
  const Mat3 r = test_rotation();
  return Sym3::symmetric_part(r * kValues.asDiagonal() * r.transpose());
}

TEST(PlaceSources, EquallySpacedAndCentred) {
  const ConstantField f;
  // Length 1.05 in unequal segments; spacing 0.2 fits 6 sources (5 gaps =
  // 1.0) with 0.025 left over at each end.
  const Trajectory t = polyline({Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0.55, 0, 0),
                                 Vec3(0.6, 0, 0), Vec3(1.05, 0, 0)});
  const std::vector<Vec3> c = centres(place_sources(f, t, 0.2, ColorScalar::lambda3));
  ASSERT_EQ(c.size(), 6u);
  for (std::size_t i = 0; i < c.size(); ++i)
    EXPECT_LE((c[i] - Vec3(0.025 + 0.2 * static_cast<double>(i), 0, 0)).norm(), 1e-12) << i;
}

// Round a closed loop the sources go evenly, as many as the spacing
// nearest fits, with none doubled where the loop closes: a loop of 20.05
// spacings, placed as an open run (21 sources over 20 spacings, centred),
// has its first and last source a twentieth of a spacing apart, a blend
// swollen at the seam.
TEST(PlaceSources, EvenlyRoundALoopWithNoSeam) {
  const ConstantField f;
  std::vector<Vec3> circle;
  for (int i = 0; i <= 2000; ++i) circle.emplace_back(std::cos(2 * M_PI * i / 2000), std::sin(2 * M_PI * i / 2000), 0);
  Trajectory loop = polyline(circle);
  const double spacing = loop.length() / 20.05;
  const std::vector<Vec3> open = centres(place_sources(f, loop, spacing, ColorScalar::lambda3));
  ASSERT_EQ(open.size(), 21u);
  EXPECT_LT((open.front() - open.back()).norm(), 0.1 * spacing);
  loop.forward_stop = loop.backward_stop = StopReason::closed;
  ASSERT_TRUE(loop.closed());
  const std::vector<Vec3> c = centres(place_sources(f, loop, spacing, ColorScalar::lambda3));
  ASSERT_EQ(c.size(), 20u);
  for (std::size_t i = 0; i < c.size(); ++i)
    EXPECT_NEAR((c[(i + 1) % c.size()] - c[i]).norm(), 2 * std::sin(M_PI / 20), 1e-5) << i;
}

TEST(PlaceSources, WholeNumberOfSpacingsReachesBothEnds) {
  const ConstantField f;
  const Trajectory t = polyline({Vec3(0, 0, 0), Vec3(0.3, 0, 0), Vec3(1.0, 0, 0)});
  const std::vector<Vec3> c = centres(place_sources(f, t, 0.1, ColorScalar::lambda3));
  ASSERT_EQ(c.size(), 11u);  // 1.0 / 0.1 is 9.999… in floating point
  EXPECT_LE((c.front() - t.points.front()).norm(), 1e-12);
  EXPECT_LE((c.back() - t.points.back()).norm(), 1e-12);
}

TEST(PlaceSources, FollowsArcLengthAroundCorners) {
  const ConstantField f;
  const Trajectory t = polyline({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)});
  const std::vector<Vec3> c = centres(place_sources(f, t, 0.5, ColorScalar::lambda3));
  const std::vector<Vec3> expected{Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(1, 0, 0),
                                   Vec3(1, 0.5, 0), Vec3(1, 1, 0)};
  ASSERT_EQ(c.size(), expected.size());
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_LE((c[i] - expected[i]).norm(), 1e-12) << i;
}

TEST(PlaceSources, DegenerateTrajectories) {
  ConstantField f;
  EXPECT_TRUE(place_sources(f, Trajectory{}, 0.1, ColorScalar::lambda3).empty());
  const std::vector<Vec3> one =
      centres(place_sources(f, polyline({Vec3(1, 2, 3)}), 0.1, ColorScalar::lambda3));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], Vec3(1, 2, 3));
  // Shorter than the spacing: one source, in the middle.
  const std::vector<Vec3> mid = centres(
      place_sources(f, polyline({Vec3(0, 0, 0), Vec3(0, 0.04, 0)}), 0.1, ColorScalar::lambda3));
  ASSERT_EQ(mid.size(), 1u);
  EXPECT_LE((mid[0] - Vec3(0, 0.02, 0)).norm(), 1e-15);
}

TEST(PlaceSources, SkipsPointsOutsideField) {
  ConstantField f;
  f.box = {Vec3(-1, -1, -1), Vec3(0.5, 1, 1)};
  const Trajectory t = polyline({Vec3(0, 0, 0), Vec3(1, 0, 0)});
  const std::vector<Vec3> c = centres(place_sources(f, t, 0.25, ColorScalar::lambda3));
  ASSERT_EQ(c.size(), 3u);  // 0, 0.25, 0.5 inside; 0.75, 1 outside
  for (const Vec3& p : c) EXPECT_TRUE(f.box.contains(p));
}

TEST(PlaceSources, RejectsBadSpacing) {
  const ConstantField f;
  const Trajectory t = polyline({Vec3(0, 0, 0), Vec3(1, 0, 0)});
  EXPECT_THROW(place_sources(f, t, 0.0, ColorScalar::lambda3), std::invalid_argument);
  EXPECT_THROW(place_sources(f, t, -1.0, ColorScalar::lambda3), std::invalid_argument);
}

// Beads whose half-length along the line is the distance from the origin
// plus 0.05: growing along a straight line, so each gap has its own size.
BeadRule growing_beads(double overlap) {
  BeadRule rule;
  rule.overlap = overlap;
  rule.least_step = 1e-3;
  rule.half_length = [](const GlyphSource& s) { return 0.05 + 0.1 * s.centre.norm(); };
  return rule;
}

SourceMaker constant_maker(const ConstantField& f) {
  return [&](const Vec3& p) -> std::optional<GlyphSource> {
    const std::optional<Sym3> t = f.sample(p);
    if (!t) return std::nullopt;
    return make_source(p, *t, ColorScalar::lambda1);
  };
}

TEST(PlaceBeads, NeighboursTouchTipToTip) {
  const ConstantField f;
  const Trajectory t = polyline({Vec3(0, 0, 0), Vec3(0.7, 0, 0), Vec3(2, 0, 0)});
  for (double overlap : {0.0, 0.3, -0.2}) {
    const BeadRule rule = growing_beads(overlap);
    const std::vector<GlyphSource> beads = place_beads(t, rule, constant_maker(f));
    ASSERT_GE(beads.size(), 5u) << overlap;
    for (std::size_t i = 1; i < beads.size(); ++i) {
      // The gap between centres is (1 − overlap) times the two
      // half-lengths: the fixed point settles far below a glyph's size.
      const double gap = (beads[i].centre - beads[i - 1].centre).norm();
      const double reach = (1.0 - overlap) * (rule.half_length(beads[i]) + rule.half_length(beads[i - 1]));
      EXPECT_NEAR(gap, reach, 1e-3 * reach) << overlap << " bead " << i;
    }
    // The run is centred: each end keeps less than a bead's length of line
    // (the longest, 2 × 0.25, at the far end), so no bead is missing there.
    const double front = beads.front().centre.x(), back = 2.0 - beads.back().centre.x();
    EXPECT_GE(front, 0.0);
    EXPECT_GE(back, 0.0);
    EXPECT_LT(std::max(front, back), (1.0 - overlap) * 2.0 * 0.25) << overlap;
    EXPECT_LT(front, back) << overlap;  // half the first walk's rest, and the rest grows with the beads
  }
}

TEST(PlaceBeads, SkipsWhereNoGlyphCanBeMadeAndRefusesBadRules) {
  ConstantField f;
  f.box = {Vec3(-1, -1, -1), Vec3(0.5, 1, 1)};
  const Trajectory t = polyline({Vec3(0, 0, 0), Vec3(1, 0, 0)});
  const std::vector<GlyphSource> beads = place_beads(t, growing_beads(0.0), constant_maker(f));
  ASSERT_FALSE(beads.empty());
  for (const GlyphSource& b : beads) EXPECT_TRUE(f.box.contains(b.centre));
  EXPECT_TRUE(place_beads(Trajectory{}, growing_beads(0.0), constant_maker(f)).empty());
  BeadRule bad = growing_beads(1.0);
  EXPECT_THROW(place_beads(t, bad, constant_maker(f)), std::invalid_argument);
  bad = growing_beads(0.0);
  bad.least_step = 0.0;
  EXPECT_THROW(place_beads(t, bad, constant_maker(f)), std::invalid_argument);
}

TEST(MapRadii, EachMapping) {
  GlyphMapping m;
  m.scale = 2.0;
  m.floor = 0.0;
  m.mapping = RadiusMapping::linear;
  EXPECT_LE((map_radii(kValues, m) - Vec3(8.0, 0.5, 2.0)).norm(), 1e-15);
  m.mapping = RadiusMapping::sqrt;
  EXPECT_LE((map_radii(kValues, m) - Vec3(4.0, 1.0, 2.0)).norm(), 1e-15);
  m.mapping = RadiusMapping::normalized;
  EXPECT_LE((map_radii(kValues, m) - Vec3(2.0, 0.125, 0.5)).norm(), 1e-15);
  // Normalised radii do not depend on the tensor's size.
  EXPECT_LE((map_radii(1e-3 * kValues, m) - Vec3(2.0, 0.125, 0.5)).norm(), 1e-15);
  EXPECT_LE((map_radii(Vec3::Zero(), m) - Vec3::Constant(2.0)).norm(), 0.0);
  m.mapping = RadiusMapping::constant;
  EXPECT_EQ(map_radii(kValues, m), Vec3::Constant(2.0));
}

TEST(MapRadii, FloorAndCeiling) {
  GlyphMapping m;
  m.mapping = RadiusMapping::linear;
  m.scale = 2.0;
  m.floor = 0.6;
  EXPECT_LE((map_radii(kValues, m) - Vec3(8.0, 0.6, 2.0)).norm(), 1e-15);
  // The ceiling scales the whole glyph, (8, 0.5, 2) → (3, 0.1875, 0.75),
  // keeping its shape; the floor then lifts the smallest radius.
  m.ceiling = 3.0;
  EXPECT_LE((map_radii(kValues, m) - Vec3(3.0, 0.6, 0.75)).norm(), 1e-15);
  // The default floor keeps a zero eigenvalue from giving a flat glyph.
  const GlyphMapping defaults;
  EXPECT_GT(map_radii(Vec3(1, 0, 0), defaults).minCoeff(), 0.0);
}

TEST(ColorScalar, Choices) {
  EXPECT_EQ(color_scalar(kValues, ColorScalar::lambda1), 4.0);
  EXPECT_EQ(color_scalar(kValues, ColorScalar::lambda2), 0.25);
  EXPECT_EQ(color_scalar(kValues, ColorScalar::lambda3), -1.0);
  EXPECT_NEAR(color_scalar(kValues, ColorScalar::mean), 3.25 / 3.0, 1e-15);
  // Von Mises: uniaxial stress σ gives |σ|, pure shear τ gives √3·τ,
  // hydrostatic stress gives 0.
  EXPECT_NEAR(color_scalar(Vec3(5, 0, 0), ColorScalar::von_mises), 5.0, 1e-14);
  EXPECT_NEAR(color_scalar(Vec3(0, 0, -5), ColorScalar::von_mises), 5.0, 1e-14);
  EXPECT_NEAR(color_scalar(Vec3(2, 0, -2), ColorScalar::von_mises), 2.0 * std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(color_scalar(Vec3(7, 7, 7), ColorScalar::von_mises), 0.0, 1e-14);
}

TEST(MakeSource, AxesAreEigenvectors) {
  GlyphMapping m;
  m.mapping = RadiusMapping::sqrt;
  const Sym3 s = test_tensor();
  const GlyphSource src = make_source(Vec3(1, 2, 3), s, m, ColorScalar::lambda1);
  EXPECT_EQ(src.centre, Vec3(1, 2, 3));
  EXPECT_LE((src.eigenvalues - kValues).norm(), 1e-12);
  EXPECT_NEAR(src.scalar, 4.0, 1e-12);
  EXPECT_NEAR(src.axes.determinant(), 1.0, 1e-12);
  const Mat3 r = test_rotation();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(std::abs(src.axes.col(k).dot(r.col(k))), 1.0, 1e-12) << k;
    EXPECT_LE((s.matrix() * src.axes.col(k) - kValues(k) * src.axes.col(k)).norm(), 1e-12);
  }
  // The renderer's shape matrix V diag(r²) Vᵀ has the tensor's eigenvectors,
  // with the mapped radii squared as eigenvalues.
  const Vec3 r2 = src.radii.cwiseProduct(src.radii);
  const Mat3 shape = src.axes * r2.asDiagonal() * src.axes.transpose();
  for (int k = 0; k < 3; ++k)
    EXPECT_LE((shape * r.col(k) - r2(k) * r.col(k)).norm(), 1e-12) << k;
  EXPECT_LE((src.radii - Vec3(2.0, 0.5, 1.0)).norm(), 1e-12);
}

TEST(MakeSource, LinearMappingOfPositiveTensorIsTheTensor) {
  const Mat3 r = test_rotation();
  const Sym3 s = Sym3::symmetric_part(r * Vec3(3, 2, 0.5).asDiagonal() * r.transpose());
  GlyphMapping m;
  m.floor = 0.0;
  const GlyphSource src = make_source(Vec3::Zero(), s, m, ColorScalar::lambda3);
  const Mat3 rebuilt = src.axes * src.radii.asDiagonal() * src.axes.transpose();
  EXPECT_LE((rebuilt - s.matrix()).norm(), 1e-12);
}

GlyphPipelineSpec point_load_scene() {
  GlyphPipelineSpec spec;
  SeedGridSpec grid;
  grid.corner = Vec3(-0.6, -0.6, -0.2);
  grid.edge_u = Vec3(1.2, 0, 0);
  grid.edge_v = Vec3(0, 1.2, 0);
  grid.n = grid.m = 3;
  spec.seeds.grids.push_back(grid);
  spec.trajectory.families = {EigenFamily::minor};
  spec.trajectory.step = 0.02;
  spec.trajectory.max_length = 1.0;
  spec.spacing = 0.1;
  return spec;
}

TEST(GlyphPipeline, AutomaticLengthsFollowTheDataSize) {
  GlyphPipelineSpec spec = point_load_scene();
  spec.data.point_load.bounds = Box3{Vec3(-2, -2, -2), Vec3(2, 2, 2)};
  spec.seeds.grids.clear();
  spec.seeds.points = {Vec3(0, 0, 0)};  // on the axis: a straight trajectory
  spec.trajectory.step.reset();
  spec.trajectory.max_length.reset();
  spec.spacing.reset();
  const GlyphScene scene = build_glyph_scene(spec, 0.5);
  const double diagonal = spec.data.point_load.bounds.diagonal();
  ASSERT_GE(scene.sources.size(), 3u);
  for (std::size_t i = 1; i < scene.sources.size(); ++i)
    EXPECT_NEAR((scene.sources[i].centre - scene.sources[i - 1].centre).norm(), diagonal / 40.0, 1e-6);
  // From the top face to the bottom face: the whole 4-unit height, which a
  // fixed default step or length could not know about.
  EXPECT_NEAR(scene.trajectories[0].length(), 4.0, 1e-6);
}

TEST(GlyphPipeline, PointLoadAlongTrajectories) {
  const GlyphPipelineSpec spec = point_load_scene();
  const GlyphScene scene = build_glyph_scene(spec, 0.5);
  EXPECT_EQ(scene.domain.lo, spec.data.point_load.bounds.lo);
  EXPECT_EQ(scene.domain.hi, spec.data.point_load.bounds.hi);
  ASSERT_EQ(scene.trajectories.size(), 9u);
  // Seeds are cell centres of the grid, in order, x fastest.
  EXPECT_LE((scene.trajectories[0].points[scene.trajectories[0].seed_index] -
             Vec3(-0.4, -0.4, -0.2)).norm(), 1e-15);
  EXPECT_LE((scene.trajectories[5].points[scene.trajectories[5].seed_index] -
             Vec3(0.4, 0.0, -0.2)).norm(), 1e-15);
  std::size_t expected_sources = 0;
  for (const Trajectory& t : scene.trajectories) {
    EXPECT_GT(t.points.size(), 10u);  // minor lines are well defined here
    expected_sources += static_cast<std::size_t>(std::floor(t.length() / *spec.spacing + 1e-9)) + 1;
  }
  EXPECT_EQ(scene.sources.size(), expected_sources);
  for (const GlyphSource& s : scene.sources) {
    EXPECT_TRUE(scene.domain.contains(s.centre)) << s.centre.transpose();
    EXPECT_LT(s.scalar, 0.0);  // λ3 is compressive under a downward load
  }
  // Deterministic: a second run gives identical output.
  const GlyphScene again = build_glyph_scene(spec, 0.5);
  ASSERT_EQ(again.sources.size(), scene.sources.size());
  for (std::size_t i = 0; i < scene.sources.size(); ++i)
    EXPECT_EQ(again.sources[i].centre, scene.sources[i].centre);
}

TEST(GlyphPipeline, AtSeeds) {
  GlyphPipelineSpec spec = point_load_scene();
  spec.placement = SourcePlacement::at_seeds;
  spec.seeds.points = {Vec3(0.1, 0.2, -0.3), Vec3(5, 5, 5)};  // the second is outside
  const GlyphScene scene = build_glyph_scene(spec, 0.5);
  EXPECT_TRUE(scene.trajectories.empty());
  ASSERT_EQ(scene.sources.size(), 1u + 9u);
  EXPECT_EQ(scene.sources[0].centre, Vec3(0.1, 0.2, -0.3));  // explicit points first
  const PointLoadField f(spec.data.point_load);
  const GlyphSource expected =
      make_source(Vec3(0.1, 0.2, -0.3), f.stress(Vec3(0.1, 0.2, -0.3)), scene.values.mapping, scene.color);
  EXPECT_LE((scene.sources[0].radii - expected.radii).norm(), 1e-15);
  EXPECT_EQ(scene.sources[0].scalar, expected.scalar);
}

TEST(GlyphPipeline, SampledGridFollowsAnalyticField) {
  GlyphPipelineSpec spec = point_load_scene();
  spec.trajectory.max_length = 0.5;
  const GlyphScene analytic = build_glyph_scene(spec, 0.5);
  spec.data.sample_grid = {41, 41, 41};
  const GlyphScene gridded = build_glyph_scene(spec, 0.5);
  ASSERT_EQ(gridded.trajectories.size(), analytic.trajectories.size());
  ASSERT_EQ(gridded.sources.size(), analytic.sources.size());
  double worst = 0, worst_radius = 0;
  for (std::size_t i = 0; i < analytic.sources.size(); ++i) {
    worst = std::max(worst, (gridded.sources[i].centre - analytic.sources[i].centre).norm());
    worst_radius = std::max(worst_radius,
                            (gridded.sources[i].radii - analytic.sources[i].radii).norm() /
                                analytic.sources[i].radii.norm());
  }
  EXPECT_LT(worst, 0.01);
  EXPECT_LT(worst_radius, 0.05);
  EXPECT_GT(worst, 0.0);  // the grid path really was taken
}

TEST(GlyphPipeline, MakeFieldChoosesGridOnlyWhenAllDimsGiven) {
  DataSpec d;
  EXPECT_NE(dynamic_cast<PointLoadField*>(make_field(d).field.get()), nullptr);
  d.sample_grid = {5, 5, 1};
  EXPECT_NE(dynamic_cast<PointLoadField*>(make_field(d).field.get()), nullptr);
  d.sample_grid = {5, 6, 7};
  EXPECT_NE(dynamic_cast<UniformGridField*>(make_field(d).field.get()), nullptr);
}

TEST(GlyphPipeline, SignedShapesAreBeadsOfTheirOwnLength) {
  GlyphPipelineSpec spec = point_load_scene();
  spec.spacing.reset();
  spec.signed_shapes = true;
  const double extent = 0.5;
  const GlyphScene scene = build_glyph_scene(spec, extent);
  ASSERT_TRUE(scene.values.beads);
  EXPECT_EQ(*scene.values.beads, 0.0);
  ASSERT_GE(scene.sources.size(), 20u);
  // Minor lines: the glyph's third axis runs along the line. Consecutive
  // beads of one line (the step between them along that axis; across it
  // a new line has begun) touch tip to tip: their length along the line is
  // their third radius.
  std::size_t touching = 0;
  for (std::size_t i = 1; i < scene.sources.size(); ++i) {
    const GlyphSource &a = scene.sources[i - 1], &b = scene.sources[i];
    const Vec3 step = b.centre - a.centre;
    const double reach = extent * (a.radii[2] + b.radii[2]);
    if (std::fabs(b.axes.col(2).dot(step.normalized())) < 0.95 || step.norm() > 2.0 * reach) continue;
    EXPECT_NEAR(step.norm(), reach, 0.02 * reach) << i;
    ++touching;
  }
  EXPECT_GE(touching, scene.sources.size() - 2 * scene.trajectories.size());
  // A spacing given keeps sources every spacing; the sizes come from the
  // sources at that spacing either way, so beads leave them as they are.
  spec.spacing = scene.values.spacing;
  const GlyphScene spaced = build_glyph_scene(spec, extent);
  EXPECT_FALSE(spaced.values.beads);
  EXPECT_EQ(spaced.values.mapping.scale, scene.values.mapping.scale);
}

}  // namespace
}  // namespace hsb
