#pragma once
// Polylines drawn as round tubes of one radius: the domain's edges and the
// trajectories. Each segment is a capsule (a cylinder with a ball at each
// end, so consecutive segments join smoothly), held as one primitive of an
// Embree user geometry and intersected in double precision here.
//
// Embree's own round curves would do, but their float kernels round
// differently on each instruction set (AVX2 fuses multiply-adds), so a
// tube's silhouette pixels would change with the processor; these give the
// same bytes on every one.

#include <embree3/rtcore.h>

#include <vector>

#include "base/box3.h"

namespace hsb {

// The first t in [tmin, tmax] where the ray o + t d enters the capsule of
// radius r around the segment [a, b], or a negative value; `normal` is then
// the capsule's outward unit normal there. A ray starting inside sees no
// entry.
double ray_capsule(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, double r, double tmin, double tmax,
                   Vec3& normal);

class ContextLines {
 public:
  // Every polyline of two points or more; shorter ones draw nothing.
  ContextLines(const std::vector<const std::vector<Vec3>*>& lines, double radius);
  ContextLines(const ContextLines&) = delete;
  ContextLines& operator=(const ContextLines&) = delete;

  // Adds the tubes to `scene` with Embree geometry mask `mask` and returns
  // the geometry's ID. This object must outlive the scene.
  unsigned attach_to(RTCDevice device, RTCScene scene, unsigned mask) const;

 private:
  static void bounds(const RTCBoundsFunctionArguments* args);
  static void intersect(const RTCIntersectFunctionNArguments* args);
  static void occluded(const RTCOccludedFunctionNArguments* args);

  struct Segment {
    Vec3 a, b;
  };
  std::vector<Segment> segments_;
  double radius_;
  double margin_;  // how far the boxes Embree sees are widened
};

}  // namespace hsb
