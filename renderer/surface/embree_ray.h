#pragma once
// Embree rays from double-precision origin and direction.

#include <embree3/rtcore.h>

#include "base/vec3.h"

namespace hsb {

// Whether Embree can be handed the ray. Its kernels assume every origin
// and direction coordinate within ±1.844e18 and no NaN, and a build with
// assertions (Debian's) aborts the whole process on any other ray. Such a
// ray is not traced; the caller counts it (TraceStats::untraceable_rays),
// and the render says so.
inline bool embree_can_trace(const Vec3& o, const Vec3& d, double tnear, double tfar) {
  constexpr double limit = 1.8e18;
  return (o.array().abs() <= limit).all() && (d.array().abs() <= limit).all() && tnear >= 0.0 && tnear <= tfar;
}

// Lane i of an N-wide ray packet; a single RTCRay is the packet with N = 1.
// `index` is the caller's number for the ray, which callbacks read back
// (ray_packets.h). The ray meets the geometries whose mask shares a bit
// with `mask`.
inline void set_embree_ray(RTCRayN* ray, unsigned n, unsigned i, unsigned index, const Vec3& o, const Vec3& d,
                           float tnear, float tfar, unsigned mask = 0xFFFFFFFFu) {
  RTCRayN_org_x(ray, n, i) = float(o.x());
  RTCRayN_org_y(ray, n, i) = float(o.y());
  RTCRayN_org_z(ray, n, i) = float(o.z());
  RTCRayN_dir_x(ray, n, i) = float(d.x());
  RTCRayN_dir_y(ray, n, i) = float(d.y());
  RTCRayN_dir_z(ray, n, i) = float(d.z());
  RTCRayN_tnear(ray, n, i) = tnear;
  RTCRayN_tfar(ray, n, i) = tfar;
  RTCRayN_time(ray, n, i) = 0.0f;
  RTCRayN_mask(ray, n, i) = mask;
  RTCRayN_id(ray, n, i) = index;
  RTCRayN_flags(ray, n, i) = 0;
}

// The same with its hit record cleared, for rtcIntersect.
inline void set_embree_ray(RTCRayHitN* rayhit, unsigned n, unsigned i, unsigned index, const Vec3& o, const Vec3& d,
                           float tnear, float tfar, unsigned mask = 0xFFFFFFFFu) {
  set_embree_ray(RTCRayHitN_RayN(rayhit, n), n, i, index, o, d, tnear, tfar, mask);
  RTCHitN* hit = RTCRayHitN_HitN(rayhit, n);
  RTCHitN_geomID(hit, n, i) = RTC_INVALID_GEOMETRY_ID;
  RTCHitN_instID(hit, n, i, 0) = RTC_INVALID_GEOMETRY_ID;
}

// Lane i of an N-wide packet a callback is handed, as double vectors.
inline Vec3 embree_ray_origin(RTCRayN* ray, unsigned n, unsigned i) {
  return {RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i)};
}
inline Vec3 embree_ray_direction(RTCRayN* ray, unsigned n, unsigned i) {
  return {RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i)};
}

inline RTCRayHit make_embree_ray(const Vec3& o, const Vec3& d, float tnear, float tfar) {
  RTCRayHit rh{};
  set_embree_ray(reinterpret_cast<RTCRayHitN*>(&rh), 1, 0, 0, o, d, tnear, tfar);
  return rh;
}

}  // namespace hsb
