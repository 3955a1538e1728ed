#include "renderer/surface/ray_span.h"

#include <cmath>

namespace hsb {

// The span BVH's callback spends most of a render here, one source against
// a packet of rays. The lane loop has no branches so the compiler turns it
// into SIMD; the clones let one portable binary use AVX-512 or AVX2 where
// the processor has them (picked once, when the program loads).
__attribute__((target_clones("avx512f", "avx2", "default")))
unsigned ray_spans(const BlobSource& s, const RayLanes& __restrict rays, int count,
                   SpanLanes& __restrict spans) {
  const double w[9] = {s.w[0], s.w[1], s.w[2], s.w[3], s.w[4], s.w[5], s.w[6], s.w[7], s.w[8]};
  const double cx = s.centre[0], cy = s.centre[1], cz = s.centre[2];
  std::int64_t inside[kMaxPacket];  // as wide as a double, so the loop keeps one vector width
  for (int i = 0; i < count; ++i) {
    // In the source's scaled frame q(t) = W(o − c) + t W d, and g = |q|².
    const double px = rays.ox[i] - cx, py = rays.oy[i] - cy, pz = rays.oz[i] - cz;
    const double wp0 = w[0] * px + w[1] * py + w[2] * pz;
    const double wp1 = w[3] * px + w[4] * py + w[5] * pz;
    const double wp2 = w[6] * px + w[7] * py + w[8] * pz;
    const double wd0 = w[0] * rays.dx[i] + w[1] * rays.dy[i] + w[2] * rays.dz[i];
    const double wd1 = w[3] * rays.dx[i] + w[4] * rays.dy[i] + w[5] * rays.dz[i];
    const double wd2 = w[6] * rays.dx[i] + w[7] * rays.dy[i] + w[8] * rays.dz[i];
    const double a = wd0 * wd0 + wd1 * wd1 + wd2 * wd2;
    const double half_b = wd0 * wp0 + wd1 * wp1 + wd2 * wp2;
    // g(t) = a t² + 2 half_b t + |Wp|². Whether the ray enters at all is
    // decided by g at the closest approach t_c; it is computed as |q(t_c)|²
    // rather than |Wp|² − half_b²/a, which cancels catastrophically when the
    // camera is far from a small glyph.
    const double tc = -half_b / a;
    const double q0 = wp0 + tc * wd0, q1 = wp1 + tc * wd1, q2 = wp2 + tc * wd2;
    const double g_min = q0 * q0 + q1 * q1 + q2 * q2;
    const double reach = (1.0 - g_min) / a;  // (half the support's length)²
    const double half_width = std::sqrt(reach > 0.0 ? reach : 0.0);
    const double t0 = tc - half_width > rays.tmin[i] ? tc - half_width : rays.tmin[i];
    const double t1 = tc + half_width < rays.tmax[i] ? tc + half_width : rays.tmax[i];
    spans.t0[i] = t0;
    spans.t1[i] = t1;
    spans.a[i] = a;
    spans.t_c[i] = tc;
    spans.g_min[i] = g_min;
    // Comparisons that are false for NaN: a = 0 (no direction) never enters.
    inside[i] = std::int64_t((a > 0.0) & (g_min < 1.0) & (t0 < t1));
  }
  unsigned mask = 0;
  for (int i = 0; i < count; ++i) mask |= unsigned(inside[i]) << i;
  return mask;
}

bool ray_span(const BlobSource& s, std::uint32_t index, const Vec3& o, const Vec3& d, double tmin,
              double tmax, RaySpan& span) {
  RayLanes ray;
  ray.set(0, o, d, tmin, tmax);
  SpanLanes lanes;
  if (!ray_spans(s, ray, 1, lanes)) return false;
  span = RaySpan{lanes.t0[0], lanes.t1[0], lanes.a[0], lanes.t_c[0], lanes.g_min[0], index};
  return true;
}

}  // namespace hsb
