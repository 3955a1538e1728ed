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

#include <array>

#include "renderer/surface/blob_field.h"
#include "renderer/surface/field_ray.h"
#include "renderer/surface/nearby_sources.h"

namespace hsb {

// Per-thread scratch for the field's callbacks: one FieldRay per packet lane.
using FieldRayLanes = std::array<FieldRay, kMaxPacket>;

// The context every rtcIntersect/rtcOccluded (1, 4, 8 or 16 wide) on a scene
// holding a BlobGeometry must pass. Embree hands the RTCIntersectContext
// pointer back to the callbacks, so it has to be the first member. Each ray's
// id must be its index in the caller's batch, below kMaxPacket
// (ray_packets.h): the results go to that slot.
struct FieldRayContext {
  RTCIntersectContext embree;
  FieldRayLanes* tracers = nullptr;  // per-thread scratch
  TraceStats* stats = nullptr;       // per-thread counters
  // Filled for each ray, by its id, whose hit the field geometry accepts
  // (valid while that ray's geomID is the field's).
  std::array<double, kMaxPacket> t{};
  std::array<SurfaceSample, kMaxPacket> surface{};
  // Camera rays: when set, each accepted hit's tangent planes, by ray id
  // (for the occlusion rays that will leave it, support_planes.h).
  SupportPlanes* hit_planes = nullptr;
  // Occlusion rays: the planes of the hit each one leaves, by ray id, or
  // nullptr.
  std::array<const SupportPlanes*, kMaxPacket> origin_planes{};

  FieldRayContext(FieldRayLanes& scratch, TraceStats& counters) : tracers(&scratch), stats(&counters) {
    rtcInitIntersectContext(&embree);
  }
};

// A ray and the parameter interval of it that is asked about.
struct RayInterval {
  Vec3 origin, direction;
  double tmin, tmax;
};

class BlobGeometry {
 public:
  // Builds the span BVH. `field` must outlive this object.
  BlobGeometry(RTCDevice device, const BlobField& field, const TraceSettings& settings);
  ~BlobGeometry();
  BlobGeometry(const BlobGeometry&) = delete;
  BlobGeometry& operator=(const BlobGeometry&) = delete;

  // Adds the field's user geometry to `scene`, with Embree geometry mask
  // `mask`, and returns its geometry ID.
  unsigned attach_to(RTCScene scene, unsigned mask);

  const BlobField& field() const { return field_; }

  // The box source i is listed under in the span BVH: what a ray must enter
  // for the source to matter to the surface. For a sum, its influence box.
  // For a union only each source's own level surface K = C draws (F = max K
  // reaches C exactly there, single_source.h), and its normal and colour
  // are the winning source's: the box of that level surface, the influence
  // box shrunk about the centre to the level radius (the shape's u is a
  // gauge, so {u ≤ u_C} is {u ≤ 1} scaled by u_C). With the usual kernels
  // and isovalues that is about a sixth of the volume, and as many fewer
  // boxes overlap along a ray.
  Box3 listed_bounds(std::size_t i) const;

  // For each of `count` rays (at most kMaxPacket), collects into
  // tracers[i].spans every source whose support ray i crosses within its
  // interval, in one traversal of the span BVH, up to where the ray enters
  // one source's own level surface (beyond it nothing changes the first
  // crossing, single_source.h). Returns how many boxes were tested, summed
  // over the rays. Public for the tests.
  std::size_t collect_spans(const RayInterval* rays, int count, FieldRay* tracers) const;

  // For each of `count` rays (at most kMaxPacket), the first crossing of
  // F = C in its interval, or a negative value; tracers[i] then holds the
  // spans around ray i's crossing for surface_at(). The span BVH is queried
  // a window at a time in ray order, so a ray that meets the surface early
  // never collects the sources behind it: the work per ray follows what is
  // in front of the first hit, not the depth of the scene.
  // With CrossingQuery::any (shadow rays) a ray stops at any crossing.
  // The rays are ones Embree has traced (the field geometry's callbacks):
  // within its range (embree_can_trace) by then.
  void first_crossings(const RayInterval* rays, int count, FieldRay* tracers, TraceStats& stats,
                       double* hits, CrossingQuery query = CrossingQuery::first) const;

  // Lists in `nearby` every source whose influence box meets `region`, in
  // spatial rank order, from one query of the span BVH. Returns false, with
  // `nearby` incomplete, when more than `limit` do.
  bool gather_nearby(const Box3& region, std::size_t limit, NearbySources& nearby,
                     std::vector<std::uint32_t>& scratch) const;

  // first_crossings for one ray that stays inside the region `nearby` was
  // gathered for: the same answer, with the BVH traversal replaced by a
  // SIMD pass over the list.
  double first_crossing_near(const NearbySources& nearby, const RayInterval& ray, FieldRay& tracer,
                             TraceStats& stats, CrossingQuery query = CrossingQuery::first) const;

  // The same answer by one traversal of the span BVH. The spans come in
  // another order than first_crossing_near() lists them, and the answer
  // does not depend on it (FieldRay), so either way it is the same to the
  // bit.
  double first_crossing_traversed(const RayInterval& ray, FieldRay& tracer, TraceStats& stats,
                                 CrossingQuery query = CrossingQuery::first) const;

  // Either of those for each of `count` rays (at most kMaxPacket): by the
  // list `nearby` (every ray inside its region), or, where it is nullptr,
  // each ray by its own traversal; tracers[i] is ray i's. The rays' walks
  // go side by side, as first_crossings' do; each answer is the one it
  // gets alone.
  void crossings_one_by_one(const RayInterval* rays, int count, const NearbySources* nearby, FieldRay* tracers,
                            TraceStats& stats, double* hits, CrossingQuery query = CrossingQuery::first) const;

 private:
  static void span_bounds(const RTCBoundsFunctionArguments* args);
  static void span_intersect(const RTCIntersectFunctionNArguments* args);
  // collect_spans for the rays whose bit is set in `lanes`: one traversal,
  // a packet one when there are several. A ray that enters one source's
  // own level surface collects no source beyond that point, and for an
  // `any` query none after it.
  std::size_t query_spans(const RayInterval* rays, FieldRay* tracers, unsigned lanes,
                          CrossingQuery crossing = CrossingQuery::first) const;
  // What crossings_one_by_one() does for each ray: the ray clipped to the
  // field's bounds, its spans collected there by `collect_spans` (given the
  // clipped ray), and the crossing among them started
  // (FieldRay::start_crossing): true while it waits on gauges, else `hit`
  // is its answer.
  template <class CollectSpans>
  bool start_crossing_of(const RayInterval& ray, FieldRay& tracer, TraceStats& stats, CrossingQuery query,
                         CollectSpans&& collect_spans, double& hit) const;
  static void field_bounds(const RTCBoundsFunctionArguments* args);
  static void field_intersect(const RTCIntersectFunctionNArguments* args);
  static void field_occluded(const RTCOccludedFunctionNArguments* args);

  const BlobField& field_;
  TraceSettings settings_;
  Box3 bounds_;
  double margin_;  // how far the boxes Embree sees are widened (embree_bounds.h)
  double first_window_;  // length of the first query window along a ray
  double listed_scale_;  // listed_bounds(): the level radius for a union, else 1
  // What the span BVH's callback asks of each source, worked out once: its
  // spatial rank (spatial_rank.h), its box and cylinder (source_support),
  // the level of g_e inside which it alone reaches C (inner_level_g), which
  // took a division each for every candidate box, and its influence box,
  // which the gathering of nearby sources asks of every candidate (a
  // superquadric's, superquadric_reach, takes a dozen powers).
  struct ListedSource {
    Box3 influence;
    ShapeSupport support;
    double g_inner;
    std::uint32_t rank;
  };
  std::vector<ListedSource> listed_;
  static std::vector<ListedSource> listed_sources(const BlobField& field, const std::vector<std::uint32_t>& ranks);
  RTCDevice device_;
  int packet_width_;  // the span queries' (ray_packets.h)
  RTCScene span_scene_ = nullptr;
};

}  // namespace hsb
