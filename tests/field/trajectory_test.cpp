// Tensor-line integration on fields whose trajectories are known in closed
// form: circles, straight segments, and regions where it must stop.

#include "field/tracing/trajectory.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace hsb {
namespace {

constexpr double kPi = 3.14159265358979323846;

// S = 3 t tᵀ + 2 r rᵀ + ẑ ẑᵀ: the major eigenvector is the tangent to
// circles about the z axis, so major trajectories are those circles.
struct CircleField final : TensorField {
  Box3 bounds() const override { return {Vec3(-2, -2, -1), Vec3(2, 2, 1)}; }
  std::optional<Sym3> sample(const Vec3& x) const override {
    if (!bounds().contains(x)) return std::nullopt;
    const Vec3 r = Vec3(x.x(), x.y(), 0).normalized();
    const Vec3 t = Vec3::UnitZ().cross(r);
    return Sym3::symmetric_part(3.0 * t * t.transpose() + 2.0 * r * r.transpose() +
                                Vec3::UnitZ() * Vec3::UnitZ().transpose());
  }
};

// A constant tensor on a box: trajectories are straight segments.
struct ConstantField final : TensorField {
  Box3 box{Vec3::Zero(), Vec3::Ones()};
  Sym3 value{3, 2, 1, 0, 0, 0};
  Box3 bounds() const override { return box; }
  std::optional<Sym3> sample(const Vec3& x) const override {
    if (!box.contains(x)) return std::nullopt;
    return value;
  }
};

// Anisotropic for x < 0.7, isotropic (every direction is an eigenvector)
// beyond, and weak (but anisotropic) for y > 0.8.
struct PatchyField final : TensorField {
  Box3 bounds() const override { return {Vec3::Zero(), Vec3::Ones()}; }
  std::optional<Sym3> sample(const Vec3& x) const override {
    if (!bounds().contains(x)) return std::nullopt;
    if (x.x() > 0.7) return Sym3{2, 2, 2, 0, 0, 0};
    if (x.y() > 0.8) return Sym3{0, 3e-3, 1e-3, 0, 0, 0};  // major along y
    return Sym3{1, 3, 2, 0, 0, 0};                          // major along y
  }
};

double angle_of(const Vec3& p) { return std::atan2(p.y(), p.x()); }

// Unwrapped angles along the trajectory, from the seed outwards: `sign`
// tells which way the angle should grow.
void expect_monotonic_angle(const Trajectory& t, double* forward_sign) {
  ASSERT_GT(t.points.size(), t.seed_index + 1);
  ASSERT_GT(t.seed_index, 0u);
  // Direction of the forward end decides the orientation.
  const double fwd = std::remainder(angle_of(t.points[t.seed_index + 1]) -
                                        angle_of(t.points[t.seed_index]), 2 * kPi);
  const double sign = fwd > 0 ? 1.0 : -1.0;
  for (std::size_t i = 1; i < t.points.size(); ++i) {
    const double d = std::remainder(angle_of(t.points[i]) - angle_of(t.points[i - 1]), 2 * kPi);
    EXPECT_GT(sign * d, 0.0) << "reversal at point " << i;
  }
  *forward_sign = sign;
}

TrajectoryOptions circle_options() {
  TrajectoryOptions o;
  o.step = 0.01;
  o.max_length = 2.0 * kPi;
  return o;
}

TEST(Trajectory, FollowsCircle) {
  const CircleField f;
  const Vec3 seed(1, 0, 0.3);
  const Trajectory t = trace_trajectory(f, seed, circle_options());
  EXPECT_EQ(t.points[t.seed_index], seed);
  EXPECT_EQ(t.forward_stop, StopReason::max_length);
  EXPECT_EQ(t.backward_stop, StopReason::max_length);
  // A full turn each way.
  EXPECT_GT(t.points.size(), 2 * 600u);
  for (const Vec3& p : t.points) {
    EXPECT_NEAR(std::hypot(p.x(), p.y()), 1.0, 1e-6);
    EXPECT_NEAR(p.z(), 0.3, 1e-12);
  }
  // Both ends close back on the seed after one turn.
  EXPECT_LE((t.points.front() - seed).norm(), 1e-5);
  EXPECT_LE((t.points.back() - seed).norm(), 1e-5);
  double sign = 0;
  expect_monotonic_angle(t, &sign);
}

TEST(Trajectory, RandomEigenvectorSignsDoNotReverse) {
  const CircleField f;
  const Vec3 seed(1, 0, 0.3);
  const TrajectoryOptions o = circle_options();
  std::mt19937 rng(11);
  std::bernoulli_distribution coin(0.5);
  int flips = 0;
  const DirectionSampler random_sign = [&](const Vec3& x) {
    DirectionSample d = eigen_direction(f, x, o);
    if (d.ok && coin(rng)) {
      d.direction = -d.direction;
      ++flips;
    }
    return d;
  };
  const Trajectory noisy = trace_directions(random_sign, seed, o);
  EXPECT_GT(flips, 100);  // the test really did scramble the signs
  double sign = 0;
  expect_monotonic_angle(noisy, &sign);

  // And it is the same curve as with consistent signs, in the same order
  // (the forward direction is the seed sample's, so compare up to reversal).
  const Trajectory clean = trace_trajectory(f, seed, o);
  ASSERT_EQ(noisy.points.size(), clean.points.size());
  double clean_sign = 0;
  expect_monotonic_angle(clean, &clean_sign);
  const std::size_t n = clean.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = noisy.points[i];
    const Vec3& b = sign == clean_sign ? clean.points[i] : clean.points[n - 1 - i];
    EXPECT_LE((a - b).norm(), 1e-12) << i;
  }
}

TEST(Trajectory, StraightLineEndsOnBoundary) {
  const ConstantField f;
  TrajectoryOptions o;
  o.step = 0.03;  // does not divide the half-width 0.5
  o.max_length = 10.0;
  const Trajectory t = trace_trajectory(f, Vec3(0.5, 0.5, 0.5), o);
  EXPECT_EQ(t.forward_stop, StopReason::boundary);
  EXPECT_EQ(t.backward_stop, StopReason::boundary);
  const Vec3 a = t.points.front(), b = t.points.back();
  // One end on x = 0, the other on x = 1, both inside.
  EXPECT_NEAR(std::min(a.x(), b.x()), 0.0, 1e-6);
  EXPECT_NEAR(std::max(a.x(), b.x()), 1.0, 1e-6);
  for (const Vec3& p : t.points) {
    EXPECT_TRUE(f.box.contains(p)) << p.transpose();
    EXPECT_NEAR(p.y(), 0.5, 1e-15);
    EXPECT_NEAR(p.z(), 0.5, 1e-15);
  }
  EXPECT_NEAR(t.length(), 1.0, 1e-6);
}

TEST(Trajectory, BoundaryHitAtAnAngle) {
  // Major eigenvector along (1, 1, 0)/√2. From (0.2, 0.5) the line reaches
  // y = 1 at (0.7, 1) before x = 1, and x = 0 at (0, 0.3) before y = 0.
  ConstantField f;
  const Mat3 r = Eigen::AngleAxisd(kPi / 4, Vec3::UnitZ()).toRotationMatrix();
  f.value = Sym3::symmetric_part(r * Vec3(3, 2, 1).asDiagonal() * r.transpose());
  TrajectoryOptions o;
  o.step = 0.02;
  const Trajectory t = trace_trajectory(f, Vec3(0.2, 0.5, 0.5), o);
  EXPECT_EQ(t.forward_stop, StopReason::boundary);
  EXPECT_EQ(t.backward_stop, StopReason::boundary);
  const Vec3 a = t.points.front(), b = t.points.back();
  const Vec3& low = a.x() < b.x() ? a : b;
  const Vec3& high = a.x() < b.x() ? b : a;
  EXPECT_NEAR(low.x(), 0.0, 1e-6);   // ends at (0, 0.3)
  EXPECT_NEAR(high.y(), 1.0, 1e-6);  // ends at (0.7, 1)
  EXPECT_NEAR(high.x(), 0.7, 1e-6);
}

TEST(Trajectory, MaxLengthStop) {
  ConstantField f;
  f.box = {Vec3(-5, -5, -5), Vec3(5, 5, 5)};
  TrajectoryOptions o;
  o.step = 0.03;
  o.max_length = 1.234;  // not a multiple of the step
  const Trajectory t = trace_trajectory(f, Vec3(0.1, 0.2, 0.3), o);
  EXPECT_EQ(t.forward_stop, StopReason::max_length);
  EXPECT_EQ(t.backward_stop, StopReason::max_length);
  EXPECT_NEAR(t.length(), 2.0 * o.max_length, 1e-9);
  EXPECT_NEAR((t.points.back() - t.points[t.seed_index]).norm(), o.max_length, 1e-9);
  EXPECT_NEAR((t.points.front() - t.points[t.seed_index]).norm(), o.max_length, 1e-9);

  o.max_length = 0.9;  // a multiple of the step: no sliver of a last step
  const Trajectory u = trace_trajectory(f, Vec3::Zero(), o);
  EXPECT_NEAR(u.length(), 1.8, 1e-9);
  EXPECT_EQ(u.points.size(), 2 * 30 + 1u);
}

TEST(Trajectory, MaxStepsStop) {
  ConstantField f;
  f.box = {Vec3(-5, -5, -5), Vec3(5, 5, 5)};
  TrajectoryOptions o;
  o.step = 0.01;
  o.max_steps = 7;
  const Trajectory t = trace_trajectory(f, Vec3::Zero(), o);
  EXPECT_EQ(t.forward_stop, StopReason::max_steps);
  EXPECT_EQ(t.backward_stop, StopReason::max_steps);
  EXPECT_EQ(t.points.size(), 2 * 7 + 1u);
  EXPECT_EQ(t.seed_index, 7u);
}

TEST(Trajectory, StopsAtDegenerateRegion) {
  const PatchyField f;
  TrajectoryOptions o;
  o.family = EigenFamily::minor;  // λ = 1, along x: runs into the isotropic region
  o.step = 0.01;
  const Trajectory t = trace_trajectory(f, Vec3(0.3, 0.5, 0.5), o);
  const bool forward_is_plus_x = t.points.back().x() > t.points.front().x();
  const StopReason plus_x = forward_is_plus_x ? t.forward_stop : t.backward_stop;
  const StopReason minus_x = forward_is_plus_x ? t.backward_stop : t.forward_stop;
  EXPECT_EQ(plus_x, StopReason::degenerate);
  EXPECT_EQ(minus_x, StopReason::boundary);
  const double end = forward_is_plus_x ? t.points.back().x() : t.points.front().x();
  EXPECT_LE(end, 0.7);
  EXPECT_GT(end, 0.7 - o.step);
  // Seeded inside the isotropic region: nothing to follow.
  const Trajectory s = trace_trajectory(f, Vec3(0.9, 0.5, 0.5), o);
  EXPECT_EQ(s.points.size(), 1u);
  EXPECT_EQ(s.forward_stop, StopReason::degenerate);
  EXPECT_EQ(s.backward_stop, StopReason::degenerate);
}

TEST(Trajectory, StopsAtLowMagnitude) {
  const PatchyField f;
  TrajectoryOptions o;
  o.family = EigenFamily::major;  // along y: runs into the weak band y > 0.8
  o.step = 0.01;
  o.min_magnitude = 0.1;
  const Trajectory t = trace_trajectory(f, Vec3(0.3, 0.5, 0.5), o);
  const bool forward_is_plus_y = t.points.back().y() > t.points.front().y();
  EXPECT_EQ(forward_is_plus_y ? t.forward_stop : t.backward_stop, StopReason::low_magnitude);
  EXPECT_EQ(forward_is_plus_y ? t.backward_stop : t.forward_stop, StopReason::boundary);
  // Without the threshold the weak band is followed to the boundary.
  o.min_magnitude = 0.0;
  const Trajectory u = trace_trajectory(f, Vec3(0.3, 0.5, 0.5), o);
  EXPECT_EQ(u.forward_stop, StopReason::boundary);
  EXPECT_EQ(u.backward_stop, StopReason::boundary);
}

// A fibre along x that fades for x > 0.6: FA 0.67 (3, 1, 1), then 0.09
// (1.2, 1, 1), its major eigenvector still along x and well defined.
struct FadingFibre final : TensorField {
  Box3 bounds() const override { return {Vec3::Zero(), Vec3::Ones()}; }
  std::optional<Sym3> sample(const Vec3& x) const override {
    if (!bounds().contains(x)) return std::nullopt;
    return x.x() > 0.6 ? Sym3{1.2, 1, 1, 0, 0, 0} : Sym3{3, 1, 1, 0, 0, 0};
  }
};

TEST(Trajectory, StopsOnTheRegionsEdge) {
  const FadingFibre f;
  TrajectoryOptions o;
  o.step = 0.03;  // does not divide 0.3
  o.measure = [](const Vec3& l) {
    const Vec3 d = l - Vec3::Constant(l.sum() / 3.0);
    return std::sqrt(1.5) * d.norm() / l.norm();
  };
  o.min_measure = 0.3;
  const Trajectory t = trace_trajectory(f, Vec3(0.3, 0.5, 0.5), o);
  const bool forward_is_plus_x = t.points.back().x() > t.points.front().x();
  EXPECT_EQ(forward_is_plus_x ? t.forward_stop : t.backward_stop, StopReason::left_region);
  EXPECT_EQ(forward_is_plus_x ? t.backward_stop : t.forward_stop, StopReason::boundary);
  // Up to the edge, as to the domain's boundary, not a step short of it.
  const double end = forward_is_plus_x ? t.points.back().x() : t.points.front().x();
  EXPECT_LE(end, 0.6);
  EXPECT_NEAR(end, 0.6, 1e-6);
  // Without a region the fading part is followed to the boundary.
  o.measure = nullptr;
  const Trajectory u = trace_trajectory(f, Vec3(0.3, 0.5, 0.5), o);
  EXPECT_EQ(u.forward_stop, StopReason::boundary);
  EXPECT_EQ(u.backward_stop, StopReason::boundary);
  // Seeded outside: nothing to follow.
  o.measure = [](const Vec3& l) { return l(0) - l(1); };
  o.min_measure = 1.0;
  EXPECT_EQ(trace_trajectory(f, Vec3(0.8, 0.5, 0.5), o).points.size(), 1u);
}

// Two bundles that meet at x = 0.5 at right angles: along x before, along
// y after, as where fibres cross.
struct CrossingBundles final : TensorField {
  Box3 bounds() const override { return {Vec3::Zero(), Vec3::Ones()}; }
  std::optional<Sym3> sample(const Vec3& x) const override {
    if (!bounds().contains(x)) return std::nullopt;
    return x.x() < 0.5 ? Sym3{3, 1, 1, 0, 0, 0} : Sym3{1, 3, 1, 0, 0, 0};
  }
};

TEST(Trajectory, StopsBeforeATurnSharperThanItsLimit) {
  const CrossingBundles f;
  TrajectoryOptions o;
  o.step = 0.02;
  o.direction = TraceDirection::forward;
  Trajectory t = trace_trajectory(f, Vec3(0.1, 0.5, 0.5), o);
  // Unlimited, it turns into the other bundle.
  ASSERT_GT(t.points.back().x(), 0.45);
  EXPECT_GT(std::fabs(t.points.back().y() - 0.5), 0.2) << "it did not turn";
  // RK4 rounds the corner in steps of 45° (a step straddling the edge
  // averages two stages of each bundle): a 30° limit stops at the first.
  o.max_turn = 30.0;
  t = trace_trajectory(f, Vec3(0.1, 0.5, 0.5), o);
  EXPECT_EQ(t.forward_stop, StopReason::sharp_turn);
  EXPECT_LT(t.points.back().x(), 0.5);
  EXPECT_GT(t.points.back().x(), 0.5 - 2.0 * o.step);
  // (A step whose last stage alone reached the other bundle turned 11°.)
  for (const Vec3& p : t.points) EXPECT_NEAR(p.y(), 0.5, 0.5 * o.step) << "it followed the other bundle";
  // A limit it never reaches changes nothing.
  o.max_turn = 60.0;
  EXPECT_NE(trace_trajectory(f, Vec3(0.1, 0.5, 0.5), o).forward_stop, StopReason::sharp_turn);
}

// Two fibre bundles crossing at right angles in the plane z = ½: A along
// x (|y − ½| < 0.1), B along y (|x − ½| < 0.1). Where they cross the
// tensor is planar (λ1 = λ2), as a voxel holding both bundles is; outside
// both it is isotropic.
struct CrossingFibres final : TensorField {
  Box3 bounds() const override { return {Vec3::Zero(), Vec3::Ones()}; }
  std::optional<Sym3> sample(const Vec3& x) const override {
    if (!bounds().contains(x)) return std::nullopt;
    const bool in_a = std::fabs(x.y() - 0.5) < 0.1, in_b = std::fabs(x.x() - 0.5) < 0.1;
    if (in_a && in_b) return Sym3{3, 3, 1, 0, 0, 0};
    if (in_a) return Sym3{3, 1, 1, 0, 0, 0};
    if (in_b) return Sym3{1, 3, 1, 0, 0, 0};
    return Sym3{2, 2, 2, 0, 0, 0};
  }
};

// The eigenvector stops where the bundles cross (its eigenvalue is no
// longer apart from the next); a tensorline goes straight through, on
// along its own bundle to the far side, as a fibre does.
TEST(Trajectory, TensorlinesCrossWhereTheEigenvectorStops) {
  const CrossingFibres f;
  TrajectoryOptions o;
  o.step = 0.01;
  o.direction = TraceDirection::forward;
  Trajectory t = trace_trajectory(f, Vec3(0.1, 0.5, 0.5), o);
  if (t.points.back().x() < 0.1) {  // forward went −x: trace the other way
    o.direction = TraceDirection::backward;
    t = trace_trajectory(f, Vec3(0.1, 0.5, 0.5), o);
  }
  EXPECT_LT(t.points.back().x(), 0.4 + 1e-9);
  EXPECT_GT(t.points.back().x(), 0.4 - o.step);
  for (const double puncture : {0.0, 0.5, 1.0}) {
    o.tensorlines = true;
    o.puncture = puncture;
    const Trajectory line = trace_trajectory(f, Vec3(0.1, 0.5, 0.5), o);
    EXPECT_NEAR(line.points.back().x(), 1.0, 1e-5) << "puncture " << puncture;
    for (const Vec3& p : line.points) ASSERT_NEAR(p.y(), 0.5, 1e-12) << "puncture " << puncture;
  }
}

// Where the tensor is linear (c_l = 1), a tensorline is the eigenvector's
// line to the bit; where it is not, the line keeps part of its heading.
TEST(Trajectory, TensorlinesAreEigenvectorLinesWhereTheTensorIsLinear) {
  struct LinearCircles final : TensorField {
    Box3 bounds() const override { return {Vec3(-2, -2, -1), Vec3(2, 2, 1)}; }
    std::optional<Sym3> sample(const Vec3& x) const override {
      if (!bounds().contains(x)) return std::nullopt;
      const Vec3 t = Vec3::UnitZ().cross(Vec3(x.x(), x.y(), 0).normalized());
      return Sym3::symmetric_part(t * t.transpose());  // λ = (1, 0, 0)
    }
  } linear;
  TrajectoryOptions o = circle_options();
  const Trajectory plain = trace_trajectory(linear, Vec3(1, 0, 0), o);
  o.tensorlines = true;
  const Trajectory line = trace_trajectory(linear, Vec3(1, 0, 0), o);
  ASSERT_EQ(line.points.size(), plain.points.size());
  for (std::size_t i = 0; i < line.points.size(); ++i) ASSERT_EQ(line.points[i], plain.points[i]) << i;
  // The circle field's c_l is 1/6: a tensorline bends less than the circle
  // and drifts outwards, more the less the tensor bends it.
  const CircleField circles;
  const Vec3 seed(1, 0, 0);
  double last_radius = 1.0;
  for (const double puncture : {1.0, 0.5, 0.0}) {
    o.puncture = puncture;
    o.max_length = 1.0;
    o.direction = TraceDirection::forward;
    const Trajectory bent = trace_trajectory(circles, seed, o);
    const double radius = Vec3(bent.points.back().x(), bent.points.back().y(), 0).norm();
    EXPECT_GT(radius, last_radius + 1e-3) << "puncture " << puncture;
    last_radius = radius;
  }
}

TEST(Trajectory, DegeneracyGapPerFamily) {
  // λ = (2, 2, 1): major and medium are degenerate, minor is fine.
  ConstantField f;
  f.value = Sym3{2, 1, 2, 0, 0, 0};
  TrajectoryOptions o;
  for (EigenFamily fam : {EigenFamily::major, EigenFamily::medium}) {
    o.family = fam;
    EXPECT_EQ(eigen_direction(f, Vec3::Constant(0.5), o).stop, StopReason::degenerate);
    EXPECT_FALSE(eigen_direction(f, Vec3::Constant(0.5), o).ok);
  }
  o.family = EigenFamily::minor;
  const DirectionSample d = eigen_direction(f, Vec3::Constant(0.5), o);
  ASSERT_TRUE(d.ok);
  EXPECT_NEAR(std::abs(d.direction.y()), 1.0, 1e-12);
  // A zero tensor is degenerate for every family.
  f.value = Sym3{};
  o.family = EigenFamily::minor;
  EXPECT_EQ(eigen_direction(f, Vec3::Constant(0.5), o).stop, StopReason::degenerate);
}

TEST(Trajectory, SeedOutsideDomain) {
  const ConstantField f;
  const Trajectory t = trace_trajectory(f, Vec3(2, 0.5, 0.5), TrajectoryOptions{});
  ASSERT_EQ(t.points.size(), 1u);
  EXPECT_EQ(t.points[0], Vec3(2, 0.5, 0.5));
  EXPECT_EQ(t.seed_index, 0u);
  EXPECT_EQ(t.forward_stop, StopReason::boundary);
  EXPECT_EQ(t.backward_stop, StopReason::boundary);
  EXPECT_EQ(t.length(), 0.0);
}

TEST(Trajectory, RejectsBadStep) {
  const ConstantField f;
  TrajectoryOptions o;
  o.step = 0.0;
  EXPECT_THROW(trace_trajectory(f, Vec3::Constant(0.5), o), std::invalid_argument);
}

}  // namespace
}  // namespace hsb
