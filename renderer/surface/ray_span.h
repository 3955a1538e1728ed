#pragma once
// One source seen along one ray: g(t) along the ray and the t-interval where
// g ≤ 1 (the source's support on the ray).

#include <cmath>
#include <cstdint>

#include "field/sym3.h"
#include "renderer/surface/blob_field.h"

namespace hsb {

// g is kept in vertex form g(t) = a (t − t_c)² + g_min rather than expanded,
// which would cancel catastrophically for a distant camera.
struct RaySpan {
  double t0, t1;    // support interval, clipped to the ray's [tmin, tmax]
  double a;         // dᵀMd > 0: also the square of g's directional rate
  double t_c;       // closest approach: K rises before it and falls after it
  double g_min;     // g(t_c)
  std::uint32_t source;

  double g(double t) const { return a * (t - t_c) * (t - t_c) + g_min; }
};

// Fills `span` and returns true when the ray o + t d, t ∈ [tmin, tmax],
// enters the influence ellipsoid of `s`.
inline bool ray_span(const BlobSource& s, std::uint32_t index, const Vec3& o, const Vec3& d,
                     double tmin, double tmax, RaySpan& span) {
  // In the source's scaled frame q(t) = W(o − c) + t W d, g = |q|².
  double wp[3], wd[3];
  for (int k = 0; k < 3; ++k) {
    const double w0 = s.w[3 * k], w1 = s.w[3 * k + 1], w2 = s.w[3 * k + 2];
    wp[k] = w0 * (o[0] - s.centre[0]) + w1 * (o[1] - s.centre[1]) + w2 * (o[2] - s.centre[2]);
    wd[k] = w0 * d[0] + w1 * d[1] + w2 * d[2];
  }
  const double a = wd[0] * wd[0] + wd[1] * wd[1] + wd[2] * wd[2];
  const double half_b = wd[0] * wp[0] + wd[1] * wp[1] + wd[2] * wp[2];
  if (!(a > 0.0)) return false;
  // g(t) = a t² + 2 half_b t + |Wp|². Whether the ray enters at
  // all is decided by g at the closest approach t_c; it is computed as |q(t_c)|²
  // rather than |Wp|² − half_b²/a, which cancels catastrophically when the
  // camera is far from a small glyph.
  const double tc = -half_b / a;
  const double q0 = wp[0] + tc * wd[0], q1 = wp[1] + tc * wd[1], q2 = wp[2] + tc * wd[2];
  const double g_min = q0 * q0 + q1 * q1 + q2 * q2;
  if (!(g_min < 1.0)) return false;
  const double half_width = std::sqrt((1.0 - g_min) / a);
  const double t0 = std::fmax(tc - half_width, tmin);
  const double t1 = std::fmin(tc + half_width, tmax);
  if (!(t0 < t1)) return false;
  span = RaySpan{t0, t1, a, tc, g_min, index};
  return true;
}

}  // namespace hsb
