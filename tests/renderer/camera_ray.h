#pragma once
// One camera ray through a RayScene, as the renderer traces it.

#include <cmath>

#include "renderer/render/ray_scene.h"
#include "renderer/surface/embree_ray.h"

namespace hsb {

struct CameraHit {
  unsigned geom_id;  // RTC_INVALID_GEOMETRY_ID when nothing is hit
  double t;          // the field's hit distance in double (when geom_id is the field's)
};

inline CameraHit trace_camera_ray(const RayScene& scene, const Vec3& o, const Vec3& d) {
  FieldRayLanes tracers;
  TraceStats stats;
  FieldRayContext context(tracers, stats);
  RTCRayHit rh = make_embree_ray(o, d, 0.0f, INFINITY);
  rtcIntersect1(scene.get(), &context.embree, &rh);
  return {rh.hit.geomID, context.t[0]};
}

}  // namespace hsb
