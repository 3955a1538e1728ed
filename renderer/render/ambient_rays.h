#pragma once
// Ambient occlusion rays: short rays in every direction from the glyph
// surface, whether anything blocks each within its length.
//
// Over a dense crowd of sources (fig06's cap) such a ray crosses hundreds
// of influence boxes, and a BVH traversal pays a callback for each. The
// rays of one packet of camera samples all stay within a small region,
// though, so the sources around it can be listed once (one BVH query) and
// every ray tested against the list in SIMD lanes (nearby_sources.h). The
// list is kept while the following packets' rays stay inside it. Where the
// sources are sparse a list would hold far more sources than a ray meets,
// and each ray traverses the BVH instead. Both ways give every ray the same
// spans, and the answer does not depend on their order (field_ray.h), so
// the choice, which depends on what the thread traced before, never
// changes a pixel.

#include <cstdint>
#include <vector>

#include "renderer/render/ray_scene.h"
#include "renderer/surface/nearby_sources.h"

namespace hsb {

class AmbientRays {
 public:
  // Whether each ray is blocked by the field within its interval: blocked[i]
  // is 1 or 0. planes[i] holds the tangent planes of the glyph hit ray i
  // leaves, or is nullptr (support_planes.h). `crowd` is how many sources
  // overlap, on average, where the rays start (SurfaceSample::crowd): a ray
  // crosses about that many supports, which prices the per-ray way.
  // `tracers` are scratch, a packet's rays walked side by side
  // (BlobGeometry::crossings_one_by_one); `stats` counts the work.
  void trace(const RayScene& scene, const std::vector<RayInterval>& rays,
             const std::vector<const SupportPlanes*>& planes, double crowd, FieldRayLanes& tracers,
             TraceStats& stats, std::vector<std::uint8_t>& blocked);

 private:
  // Lists the sources around `needed`, with room to spare for the next
  // packets, unless the list would be dearer than tracing each ray.
  bool cover(const BlobGeometry& blobs, const Box3& needed, double crowd);

  NearbySources nearby_;
  Box3 listed_;             // the region nearby_ covers
  bool have_list_ = false;
  std::vector<std::uint32_t> scratch_;
  double density_ = 0.0;    // sources per unit volume in the last region asked about
};

}  // namespace hsb
