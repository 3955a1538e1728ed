#pragma once
// An Embree ray from double-precision origin and direction.

#include <embree3/rtcore.h>

#include "field/sym3.h"

namespace hsb {

inline RTCRayHit make_embree_ray(const Vec3& o, const Vec3& d, float tnear, float tfar) {
  RTCRayHit rh{};
  rh.ray.org_x = float(o.x());
  rh.ray.org_y = float(o.y());
  rh.ray.org_z = float(o.z());
  rh.ray.dir_x = float(d.x());
  rh.ray.dir_y = float(d.y());
  rh.ray.dir_z = float(d.z());
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

}  // namespace hsb
