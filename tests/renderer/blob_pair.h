#pragma once
// A canonical blend for the tests: two sources with R·r = 1 (each alone a
// sphere of radius ½) centred at x = ±0.55. Each alone stops 0.05 short of
// x = 0, but there each contributes K(u = 0.55) ≈ 0.42 and the sum exceeds
// C = ½, so a ray along y through the origin hits only the blend.

#include "renderer/surface/blob_field.h"

namespace hsb {

inline BlobField blob_pair() {
  BlobField pair;
  pair.sources.push_back(make_blob_source(Vec3(-0.55, 0, 0), Mat3::Identity(), Vec3::Ones(), 1.0, {1, 0, 0}));
  pair.sources.push_back(make_blob_source(Vec3(0.55, 0, 0), Mat3::Identity(), Vec3::Ones(), 1.0, {0, 0, 1}));
  return pair;
}

// |y| where the pair's surface crosses the y axis: 2 K(x0² + y²) = ½ with
// x0 the centre as stored (single precision), by bisection.
inline double blob_pair_crossing_y() {
  const double x0 = double(0.55f);
  double lo = 0, hi = 1;
  for (int k = 0; k < 200; ++k) {
    const double y = 0.5 * (lo + hi);
    (2 * kernel_value(KernelKind::wyvill, x0 * x0 + y * y) > 0.5 ? lo : hi) = y;
  }
  return lo;
}

}  // namespace hsb
