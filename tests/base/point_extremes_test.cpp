// Least values over many points on every core: the same as one pass over
// them, whatever the points and however many threads share them.

#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "base/point_extremes.h"

namespace hsb {
namespace {

// Enough points that the reduction splits them many times over.
std::vector<Vec3> scattered_points(std::size_t count) {
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal(0.0, 10.0);
  std::vector<Vec3> points(count);
  for (Vec3& p : points) p = Vec3(normal(random), normal(random), normal(random));
  return points;
}

std::array<double, 3> values_of(const Vec3& p) {
  // A value that is NaN for some points takes no part.
  return {p.x() - 2.0 * p.y(), -p.z(), p.y() > 5.0 ? std::nan("") : p.y()};
}

std::array<double, 3> least_in_one_pass(const std::vector<Vec3>& points) {
  std::array<double, 3> least{INFINITY, INFINITY, INFINITY};
  for (const Vec3& p : points) {
    if (!p.allFinite()) continue;
    const std::array<double, 3> v = values_of(p);
    for (std::size_t k = 0; k < 3; ++k)
      if (v[k] < least[k]) least[k] = v[k];
  }
  return least;
}

TEST(PointExtremes, LeastValuesAreThoseOfOnePassOnAnyNumberOfThreads) {
  std::vector<Vec3> points = scattered_points(300000);
  points[1234] = Vec3(-1e9, NAN, 0.0);     // not finite: left out,
  points[250000] = Vec3(0.0, 0.0, INFINITY);  // though they would be least
  const std::array<double, 3> expected = least_in_one_pass(points);
  EXPECT_LT(expected[0], -50.0);
  for (const int threads : {1, 2, 5}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    const std::array<double, 3> least = least_values(points, values_of);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(least[k], expected[k]) << threads << " threads, value " << k;
  }
}

TEST(PointExtremes, NoPointsHaveNoLeastValue) {
  const std::array<double, 3> least = least_values({}, values_of);
  for (const double v : least) EXPECT_EQ(v, INFINITY);
  const std::vector<Vec3> none_finite{Vec3(NAN, 0.0, 0.0), Vec3(0.0, -INFINITY, 0.0)};
  EXPECT_EQ(least_values(none_finite, values_of)[0], INFINITY);
}

TEST(PointExtremes, TheBoundingBoxHoldsTheFinitePointsAndTouchesThem) {
  std::vector<Vec3> points = scattered_points(100000);
  points[99] = Vec3(1e300, NAN, 0.0);
  const Box3 box = bounding_box(points);
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const Vec3& p : points)
    if (p.allFinite()) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  EXPECT_EQ(box.lo, lo);
  EXPECT_EQ(box.hi, hi);
  const Box3 empty = bounding_box({});
  EXPECT_EQ(empty.lo, Vec3::Constant(INFINITY));
  EXPECT_EQ(empty.hi, Vec3::Constant(-INFINITY));
}

}  // namespace
}  // namespace hsb
