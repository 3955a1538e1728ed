#pragma once
// The sources whose influence reaches into a small region, copied out as
// structure of arrays. Meant for a bundle of short rays that all stay
// inside the region (the ambient occlusion rays of one packet of camera
// samples): one query of the span BVH for the whole bundle, then each ray
// is tested against the list in SIMD lanes, sixteen sources at a time,
// skipping the sixteens whose joint influence box it misses. Incoherent rays through a dense
// crowd of sources cost far less this way than one BVH traversal each,
// which pays a callback per influence box crossed.

#include <cstdint>
#include <vector>

#include "base/box3.h"
#include "renderer/surface/blob_field.h"
#include "renderer/surface/ray_span.h"

namespace hsb {

class NearbySources {
 public:
  void clear();
  // The field's source number `index`, of spatial rank `rank`, whose
  // influence box is `influence` (influence_bounds).
  void add(const BlobField& field, std::uint32_t index, std::uint32_t rank, const Box3& influence);
  std::size_t size() const { return size_; }

  // Appends to `spans` the span of every listed source whose support the
  // ray o + t d crosses within [tmin, tmax], in the order they were added,
  // each narrowed to its influence box as the span BVH's are.
  void collect_spans(const Vec3& o, const Vec3& d, double tmin, double tmax, std::vector<RaySpan>& spans) const;

 private:
  std::vector<SourceLanes> chunks_;  // [0, used_chunks_) are in use; kept for reuse
  std::vector<Box3> chunk_bounds_;   // each chunk's sources' influence boxes together
  std::vector<Box3> boxes_;          // each listed source's own, in the order added (narrow_to_influence)
  GlyphShape shape_ = GlyphShape::ellipsoid;
  std::size_t used_chunks_ = 0;
  std::size_t size_ = 0;
};

}  // namespace hsb
