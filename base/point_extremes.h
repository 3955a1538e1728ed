#pragma once
// Least values over many points, on every core. Framing a glyph field
// takes extremes over 14 points a glyph, 1.7 million for Teem's helix at
// 136³: a few passes that kept one thread 40 ms while the other core
// idled. The points are split the same way whatever the number of cores
// (a deterministic reduction), so the answer has the same bits on any
// machine; and a least value is the same whichever order its points come
// in, so it is also that of a single pass.

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "base/box3.h"
#include "base/vec3.h"

namespace hsb {

// The least of each value that `values(p)` gives (an std::array of
// doubles) over the finite points p; +inf where there are none. A value
// that is NaN takes no part; a largest value is the negated least of its
// negation.
template <class Values>
auto least_values(const std::vector<Vec3>& points, Values&& values) {
  using Least = std::remove_cv_t<std::remove_reference_t<std::invoke_result_t<Values&, const Vec3&>>>;
  Least none;
  none.fill(INFINITY);
  const auto fold = [](Least a, const Least& b) {
    for (std::size_t k = 0; k < a.size(); ++k) a[k] = std::min(a[k], b[k]);
    return a;
  };
  constexpr std::size_t grain = 1 << 15;
  return tbb::parallel_deterministic_reduce(
      tbb::blocked_range<std::size_t>(0, points.size(), grain), none,
      [&](const tbb::blocked_range<std::size_t>& range, Least least) {
        for (std::size_t i = range.begin(); i != range.end(); ++i)
          if (points[i].allFinite()) least = fold(least, values(points[i]));
        return least;
      },
      fold, tbb::simple_partitioner());
}

// The box around the finite ones of `points`; lo = +inf and hi = −inf
// (empty) when there are none.
inline Box3 bounding_box(const std::vector<Vec3>& points) {
  const std::array<double, 6> least = least_values(points, [](const Vec3& p) {
    return std::array<double, 6>{p.x(), p.y(), p.z(), -p.x(), -p.y(), -p.z()};
  });
  return {Vec3(least[0], least[1], least[2]), -Vec3(least[3], least[4], least[5])};
}

}  // namespace hsb
