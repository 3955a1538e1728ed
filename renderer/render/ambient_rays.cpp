#include "renderer/render/ambient_rays.h"

#include <algorithm>

namespace hsb {
namespace {

// The prices, in a ray's cycles (measured over fig06's cap): a listed
// source costs about five (a SIMD lane); a BVH traversal costs about 250
// per support it collects (a callback for each of the three or four
// influence boxes it meets per support). So a list pays up to some 50
// sources per support a ray crosses; a ray crosses about one and a half
// times as many supports as overlap where it starts.
constexpr double kListedPerCrowd = 40.0;
// Below this a ray crosses so few supports that its traversal is cheap, and
// a list is not worth its query.
constexpr double kShortestList = 256.0;
// The list covers the packet's region grown by this fraction of its size
// on every side, so that the next packets along the row still fit.
constexpr double kListMargin = 0.5;

double volume(const Box3& box) { return std::max(0.0, box.size().prod()); }

}  // namespace

bool AmbientRays::cover(const BlobGeometry& blobs, const Box3& needed, double crowd) {
  if (have_list_ && listed_.contains(needed)) return true;
  const double limit = kListedPerCrowd * crowd;
  if (limit < kShortestList) return false;
  const Vec3 margin = kListMargin * needed.size();
  const Box3 region{needed.lo - margin, needed.hi + margin};
  // The regions asked about lately foretell this one's crowd: a query that
  // would only come out too long is not made.
  const double space = volume(region);
  if (density_ * space > limit) return false;
  if (!blobs.gather_nearby(region, std::size_t(limit), nearby_, scratch_)) {
    density_ = space > 0.0 ? limit / space : density_;
    have_list_ = false;
    return false;
  }
  density_ = space > 0.0 ? double(nearby_.size()) / space : 0.0;
  listed_ = region;
  have_list_ = true;
  return true;
}

void AmbientRays::trace(const RayScene& scene, const std::vector<RayInterval>& rays,
                        const std::vector<const SupportPlanes*>& planes, double crowd, FieldRayLanes& tracers,
                        TraceStats& stats, std::vector<std::uint8_t>& blocked) {
  const std::size_t count = rays.size();
  blocked.assign(count, 0);
  // Glyphs not drawn: nothing casts a shadow.
  if (count == 0 || scene.field_id() == RTC_INVALID_GEOMETRY_ID) return;
  const BlobGeometry& blobs = scene.blobs();
  Box3 needed{rays[0].origin, rays[0].origin};
  for (const RayInterval& ray : rays) {
    const Vec3 end = ray.origin + ray.tmax * ray.direction;
    needed.extend({ray.origin.cwiseMin(end), ray.origin.cwiseMax(end)});
  }
  const bool listed = cover(blobs, needed, crowd);
  // A packet's worth at a time, their walks side by side.
  for (std::size_t first = 0; first < count; first += kMaxPacket) {
    const int n = int(std::min<std::size_t>(kMaxPacket, count - first));
    for (int i = 0; i < n; ++i) tracers[std::size_t(i)].leave_surface(planes[first + std::size_t(i)]);
    double hits[kMaxPacket];
    blobs.crossings_one_by_one(&rays[first], n, listed ? &nearby_ : nullptr, tracers.data(), stats, hits,
                               CrossingQuery::any);
    for (int i = 0; i < n; ++i) blocked[first + std::size_t(i)] = hits[i] >= 0.0 ? 1 : 0;
  }
}

}  // namespace hsb
