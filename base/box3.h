#pragma once
// Axis-aligned box, used for data-set domains and bounds.

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "base/vec3.h"

namespace hsb {

struct Box3 {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();

  bool contains(const Vec3& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
  bool contains(const Box3& o) const { return contains(o.lo) && contains(o.hi); }
  bool overlaps(const Box3& o) const {
    return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all();
  }
  void extend(const Box3& o) {
    lo = lo.cwiseMin(o.lo);
    hi = hi.cwiseMax(o.hi);
  }
  Vec3 size() const { return hi - lo; }
  Vec3 centre() const { return 0.5 * (lo + hi); }
  double diagonal() const { return size().norm(); }
  std::array<Vec3, 8> corners() const {
    std::array<Vec3, 8> c;
    for (int i = 0; i < 8; ++i)
      c[std::size_t(i)] = Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
    return c;
  }
};

// The parameter interval where the ray o + t d is inside `box`, intersected
// with [tmin, tmax]; empty (first > second) when it misses.
inline std::pair<double, double> ray_interval_in(const Box3& box, const Vec3& o, const Vec3& d, double tmin,
                                                 double tmax) {
  double lo = tmin, hi = tmax;
  for (int k = 0; k < 3; ++k) {
    const double inv = 1.0 / d[k];  // ±inf for an axis-parallel ray: the slab test still works
    double a = (box.lo[k] - o[k]) * inv, b = (box.hi[k] - o[k]) * inv;
    if (a > b) std::swap(a, b);
    if (!(a <= b)) continue;  // NaN: the ray lies in the slab's plane
    lo = std::max(lo, a);
    hi = std::min(hi, b);
  }
  return {lo, hi};
}

}  // namespace hsb
