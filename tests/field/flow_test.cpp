// Vector fields: streamlines of known flows stay on their curves and never
// turn back; streamballs take their radius from the speed; sources along a
// curve and from a list.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "field/glyphs/curve_sources.h"
#include "field/glyphs/glyph_sources.h"
#include "field/glyphs/source_list.h"
#include "field/reading/data_error.h"
#include "field/sampling/field.h"
#include "field/tracing/trajectory.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

// An analytic flow in the box [-2, 2]³.
class Flow final : public VectorField {
 public:
  explicit Flow(std::function<Vec3(const Vec3&)> v) : v_(std::move(v)) {}
  Box3 bounds() const override { return {Vec3::Constant(-2), Vec3::Constant(2)}; }
  std::optional<Vec3> sample(const Vec3& x) const override {
    if ((x.array() < -2.0).any() || (x.array() > 2.0).any()) return std::nullopt;
    return v_(x);
  }

 private:
  std::function<Vec3(const Vec3&)> v_;
};

TrajectoryOptions options(double step = 0.01, double max_length = 20.0) {
  TrajectoryOptions o;
  o.step = step;
  o.max_length = max_length;
  o.min_magnitude = 1e-6;
  return o;
}

TEST(Streamlines, ARigidRotationGivesClosedCircles) {
  const Flow rotation([](const Vec3& x) { return Vec3(-x.y(), x.x(), 0.0); });
  for (double r : {0.3, 1.0, 1.7}) {
    const Trajectory t = trace_streamline(rotation, Vec3(r, 0, 0.5), options());
    EXPECT_EQ(t.forward_stop, StopReason::closed) << r;
    EXPECT_NEAR(t.length(), 2.0 * M_PI * r, 0.02) << r;  // once round, not again
    for (const Vec3& p : t.points) {
      EXPECT_NEAR(std::hypot(p.x(), p.y()), r, 1e-6) << r;
      EXPECT_DOUBLE_EQ(p.z(), 0.5);
    }
    // Anticlockwise, as the flow goes: the first step has y > 0.
    EXPECT_GT(t.points[t.seed_index + 1].y(), 0.0);
  }
}

TEST(Streamlines, AUniformFlowGivesStraightLinesToTheBoundary) {
  const Vec3 v(1.0, 2.0, -0.5);
  const Flow uniform([&](const Vec3&) { return v; });
  const Trajectory t = trace_streamline(uniform, Vec3(0.1, -0.2, 0.3), options());
  EXPECT_EQ(t.forward_stop, StopReason::boundary);
  EXPECT_EQ(t.backward_stop, StopReason::boundary);
  const Vec3 d = v.normalized();
  for (const Vec3& p : t.points) {
    const Vec3 off = p - Vec3(0.1, -0.2, 0.3);
    EXPECT_LT((off - off.dot(d) * d).norm(), 1e-12);
  }
  // Along the flow from the backward end to the forward end.
  EXPECT_GT((t.points.back() - t.points.front()).dot(v), 0.0);
  EXPECT_NEAR(t.points.back().y(), 2.0, 1e-4);  // ends on the boundary
  const Trajectory forward_only = trace_streamline(uniform, Vec3::Zero(), [] {
    TrajectoryOptions o = options();
    o.direction = TraceDirection::forward;
    return o;
  }());
  EXPECT_EQ(forward_only.seed_index, 0u);
  EXPECT_GT(forward_only.points.size(), 2u);
}

TEST(Streamlines, NeverTurnBackAtASink) {
  // Everything flows into the origin: the streamline from (1, 0.5, 0) runs
  // in and stops at the stagnation point, where an eigenvector-style flip
  // would have sent it back out.
  const Flow sink([](const Vec3& x) { return Vec3(-x); });
  const Trajectory t = trace_streamline(sink, Vec3(1.0, 0.5, 0.0), options(0.01, 10.0));
  EXPECT_EQ(t.forward_stop, StopReason::low_magnitude);
  double last = 1e9;
  for (std::size_t i = t.seed_index; i < t.points.size(); ++i) {
    const double r = t.points[i].norm();
    EXPECT_LE(r, last + 1e-12) << "turned back at point " << i;
    last = r;
  }
  EXPECT_LT(last, 0.02);
}

TEST(Streamballs, RadiusFromTheSpeedAlongTheFlow) {
  const Vec3 v(0.0, 3.0, 4.0);  // speed 5
  GlyphSource s = make_flow_source(Vec3(1, 2, 3), v, ColorScalar::speed);
  EXPECT_DOUBLE_EQ(s.scalar, 5.0);
  EXPECT_TRUE(s.axes.col(0).isApprox(v.normalized()));
  EXPECT_NEAR(s.axes.determinant(), 1.0, 1e-12);  // right-handed
  GlyphMapping linear;
  linear.scale = 0.1;
  linear.floor = 0.0;
  std::vector<GlyphSource> sources{s};
  size_sources(sources, linear);
  EXPECT_TRUE(sources[0].radii.isApprox(Vec3::Constant(0.5)));  // a sphere, s·|v|
  GlyphMapping sqrt_mapping = linear;
  sqrt_mapping.mapping = RadiusMapping::sqrt;
  size_sources(sources, sqrt_mapping);
  EXPECT_NEAR(sources[0].radii.x(), 0.1 * std::sqrt(5.0), 1e-12);
  stretch_sources(sources, 2.0);
  EXPECT_NEAR(sources[0].radii.x(), 0.2 * std::sqrt(5.0), 1e-12);  // along the flow only
  EXPECT_NEAR(sources[0].radii.y(), 0.1 * std::sqrt(5.0), 1e-12);
}

TEST(CurveSources, EvenlyAlongACircleWithTheirShape) {
  CurveSpec circle;
  circle.kind = CurveKind::circle;
  circle.centre = Vec3(1, 0, 0);
  circle.radius = 2.0;
  circle.count = 8;
  circle.semi_axes = Vec3(0.4, 0.2, 0.1);
  const std::vector<GlyphSource> s = curve_sources(circle, 0.5);
  ASSERT_EQ(s.size(), 8u);
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_NEAR((s[i].centre - circle.centre).norm(), 2.0, 1e-3);
    EXPECT_NEAR((s[i].centre - s[(i + 1) % 8].centre).norm(), 2 * 2.0 * std::sin(M_PI / 8), 2e-3);
    EXPECT_TRUE(s[i].radii.isApprox(Vec3(0.8, 0.4, 0.2)));  // semi-axes / extent
    const Vec3 radial = (s[i].centre - circle.centre).normalized();
    EXPECT_NEAR(std::fabs(s[i].axes.col(0).dot(radial)), 0.0, 0.02);  // along the curve
    EXPECT_NEAR(s[i].axes.col(1).dot(-radial), 1.0, 0.02);            // towards the centre
    EXPECT_DOUBLE_EQ(s[i].scalar, double(i) / 8);
  }
  CurveSpec line;
  line.kind = CurveKind::line;
  line.from = Vec3(0, 0, 0);
  line.to = Vec3(3, 0, 0);
  line.count = 4;
  const std::vector<GlyphSource> l = curve_sources(line, 1.0);
  ASSERT_EQ(l.size(), 4u);
  EXPECT_TRUE(l.front().centre.isApprox(line.from));
  EXPECT_TRUE(l.back().centre.isApprox(line.to));
  EXPECT_NEAR(l[1].centre.x(), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(l.back().scalar, 1.0);
  CurveSpec helix;
  helix.turns = 2.0;
  helix.pitch = 0.5;
  helix.radius = 1.0;
  helix.count = 3;
  const std::vector<GlyphSource> h = curve_sources(helix, 1.0);
  EXPECT_NEAR(h.back().centre.z() - h.front().centre.z(), 1.0, 1e-9);
}

class SourceList : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    const auto path = test_temp_dir("source_list") / "hsb_source_list.csv";
    std::ofstream(path) << text;
    return path.string();
  }
  std::string error_of(const std::string& text) {
    try {
      read_source_list(write(text), 0.5);
    } catch (const DataError& e) {
      return e.what();
    }
    return "no error";
  }
};

TEST_F(SourceList, ColumnsInAnyOrderWithAxesOrQuaternions) {
  const auto s = read_source_list(write("# a comment\nscalar, z, y, x, r1, r2, r3, qw, qx, qy, qz\n"
                                        "7, 3, 2, 1, 0.3, 0.2, 0.1, 0.7071067811865476, 0, 0, 0.7071067811865476\n\n"
                                        "-1, 0, 0, 0, 0.1, 0.1, 0.1, 1, 0, 0, 0\n"),
                                  0.5);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_TRUE(s[0].centre.isApprox(Vec3(1, 2, 3)));
  EXPECT_TRUE(s[0].radii.isApprox(Vec3(0.6, 0.4, 0.2)));
  EXPECT_TRUE(s[0].axes.col(0).isApprox(Vec3(0, 1, 0)));  // a quarter turn about z
  EXPECT_DOUBLE_EQ(s[0].scalar, 7.0);
  const auto axes = read_source_list(write("x,y,z,r,ax,ay,az,bx,by,bz\n0,0,0,1,0,0,2,1,0,0\n"), 1.0);
  EXPECT_TRUE(axes[0].axes.col(0).isApprox(Vec3(0, 0, 1)));
  EXPECT_TRUE(axes[0].axes.col(1).isApprox(Vec3(1, 0, 0)));
  EXPECT_NEAR(axes[0].axes.determinant(), 1.0, 1e-12);
  EXPECT_TRUE(axes[0].radii.isApprox(Vec3::Ones()));
}

TEST_F(SourceList, ErrorsNameTheLineAndColumn) {
  const std::string file = write("");
  EXPECT_NE(error_of("x,y,z,r\n0,0,0,1\n1,abc,0,1\n").find("hsb_source_list.csv:3:3: y: a finite number, found \"abc\""),
            std::string::npos) << error_of("x,y,z,r\n0,0,0,1\n1,abc,0,1\n");
  EXPECT_NE(error_of("x,y,z,r\n0,0,0\n").find(":2:5: 4 values as in the header, found 3"), std::string::npos)
      << error_of("x,y,z,r\n0,0,0\n");
  EXPECT_NE(error_of("x,y,r\n").find(":1:1: a header with columns x, y and z"), std::string::npos);
  EXPECT_NE(error_of("x,y,z\n").find("r1, r2 and r3, or r"), std::string::npos);
  EXPECT_NE(error_of("x,y,z,r\n0,0,0,-1\n").find(":2:7: r: a size > 0, found -1"), std::string::npos)
      << error_of("x,y,z,r\n0,0,0,-1\n");
  EXPECT_NE(error_of("x,y,z,r,x\n").find("each column once, found \"x\" twice"), std::string::npos);
  EXPECT_NE(error_of("x,y,z,r\n0,nan,0,1\n").find("a finite number, found \"nan\""), std::string::npos);
  EXPECT_NE(error_of("# only a comment\n").find("no header row"), std::string::npos);
}

// A group of columns comes whole: a quaternion without qx once said
// "map::at"; axes without their second vector were silently ignored.
TEST_F(SourceList, ColumnGroupsComeWhole) {
  EXPECT_EQ(error_of("x,y,z,r,qw,qy,qz\n0,0,0,1,1,0,0\n"),
            write("") + ":1:9: all of the columns qw, qx, qy, qz (a quaternion), found qw qy qz without qx");
  EXPECT_EQ(error_of("x,y,z,r,ax,ay,az\n0,0,0,1,1,0,0\n"),
            write("") + ":1:9: all of the columns ax, ay, az, bx, by, bz (two axes), found ax ay az without bx by bz");
  EXPECT_EQ(error_of("x,y,z,r,r1,r2\n0,0,0,1,1,1\n"),
            write("") + ":1:9: all of the columns r1, r2, r3 (the radii), found r1 r2 without r3");
}

// A row far away could never be traced (and once rendered blank).
TEST_F(SourceList, CoordinatesBeyondTheTracersRangeAreRefused) {
  EXPECT_EQ(error_of("x,y,z,r\n0,0,0,1\n0,2e30,0,1\n"),
            write("") + ":3:3: y: a coordinate within ±1e17 (the ray tracer's single-precision range), found 2e30");
}

// Spreadsheets write UTF-8 with a byte-order mark before the header.
TEST_F(SourceList, AByteOrderMarkIsNoPartOfTheHeader) {
  const auto s = read_source_list(write("\xEF\xBB\xBFx,y,z,r\n1,2,3,0.5\n"), 0.5);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_TRUE(s[0].centre.isApprox(Vec3(1, 2, 3)));
}

}  // namespace
}  // namespace hsb
