#pragma once
// The blended field as one Embree user geometry (design §6).
//
// Two Embree scenes cooperate. The span BVH is a private scene with one user
// primitive per source, bounded by the source's influence box; its intersect
// callback never reports a hit, it only records the source's support
// interval on the ray, so one traversal collects exactly the sources whose
// influence the ray crosses. The field geometry is a single user primitive
// in the caller's top-level scene; its callbacks query the span BVH and
// sphere-trace F = C over the collected spans. Shadow rays take the same
// path through the occluded callback.

#include <embree3/rtcore.h>

#include "renderer/surface/blob_field.h"
#include "renderer/surface/field_ray.h"

namespace hsb {

// The per-ray context every rtcIntersect1/rtcOccluded1 on a scene holding a
// BlobGeometry must pass. Embree hands the RTCIntersectContext pointer back
// to the callbacks, so it has to be the first member.
struct FieldRayContext {
  RTCIntersectContext embree;
  FieldRay* tracer = nullptr;  // per-thread scratch
  TraceStats* stats = nullptr;     // per-thread counters
  // Filled when the field geometry accepts a hit (valid while the ray's
  // geomID is the field's).
  double t = 0.0;
  SurfaceSample surface;

  FieldRayContext(FieldRay& scratch, TraceStats& counters) : tracer(&scratch), stats(&counters) {
    rtcInitIntersectContext(&embree);
  }
};

class BlobGeometry {
 public:
  // Builds the span BVH. `field` must outlive this object.
  BlobGeometry(RTCDevice device, const BlobField& field, const TraceSettings& settings);
  ~BlobGeometry();
  BlobGeometry(const BlobGeometry&) = delete;
  BlobGeometry& operator=(const BlobGeometry&) = delete;

  // Adds the field's user geometry to `scene` and returns its geometry ID.
  unsigned attach_to(RTCScene scene);

  const BlobField& field() const { return field_; }

  // Collects into tracer.spans every source whose support the ray
  // o + t d crosses within [tmin, tmax]. Public for the tests.
  void collect_spans(const Vec3& o, const Vec3& d, double tmin, double tmax,
                     FieldRay& tracer) const;

  // The first crossing of F = C along the ray, or a negative value. The
  // span BVH is queried a window at a time in ray order, so a ray that meets
  // the surface early never collects the sources behind it: the work per
  // ray follows what is in front of the first hit, not the depth of the
  // scene.
  double first_crossing(const Vec3& o, const Vec3& d, double tmin, double tmax,
                        FieldRay& tracer, TraceStats& stats) const;

 private:
  static void span_bounds(const RTCBoundsFunctionArguments* args);
  static void span_intersect(const RTCIntersectFunctionNArguments* args);
  static void field_bounds(const RTCBoundsFunctionArguments* args);
  static void field_intersect(const RTCIntersectFunctionNArguments* args);
  static void field_occluded(const RTCOccludedFunctionNArguments* args);

  const BlobField& field_;
  TraceSettings settings_;
  Box3 bounds_;
  double first_window_;  // length of the first query window along a ray
  RTCDevice device_;
  RTCScene span_scene_ = nullptr;
};

}  // namespace hsb
