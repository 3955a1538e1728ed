#include "renderer/surface/blob_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "renderer/surface/embree_ray.h"
#include "renderer/surface/spatial_rank.h"

namespace hsb {
namespace {

// The span query's context: where the span BVH's callback writes. Lane i of
// the query is rays lane i, and its spans go to tracers[i].
struct SpanQueryContext {
  RTCIntersectContext embree;  // first member, see FieldRayContext
  const BlobField* field;
  RayLanes rays;
  FieldRay* tracers;
  std::size_t candidates;
};

// Rounds a double box outwards to float so the BVH never clips an ellipsoid.
void store_bounds(const Box3& box, RTCBounds* out) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  out->lower_x = std::nextafter(static_cast<float>(box.lo.x()), -inf);
  out->lower_y = std::nextafter(static_cast<float>(box.lo.y()), -inf);
  out->lower_z = std::nextafter(static_cast<float>(box.lo.z()), -inf);
  out->upper_x = std::nextafter(static_cast<float>(box.hi.x()), inf);
  out->upper_y = std::nextafter(static_cast<float>(box.hi.y()), inf);
  out->upper_z = std::nextafter(static_cast<float>(box.hi.z()), inf);
}

void check_device(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree error ") + std::to_string(int(error)) + " while " +
                             what);
}

// The active lanes of a callback's ray packet, gathered in lane order.
struct ValidLanes {
  int count = 0;
  std::array<RayInterval, kMaxPacket> rays;
  std::array<unsigned, kMaxPacket> lane;
};

ValidLanes gather_lanes(const int* valid, RTCRayN* rays, unsigned n) {
  // Embree calls back with the width of the caller's query, and no caller
  // issues packets wider than kMaxPacket. (An exception must not cross
  // Embree's C frames, hence the abort.)
  if (n > unsigned(kMaxPacket)) {
    std::fprintf(stderr, "hsb: internal error: a %u-ray packet reached the field geometry\n", n);
    std::abort();
  }
  ValidLanes lanes;
  for (unsigned i = 0; i < n; ++i) {
    if (!valid[i]) continue;
    RayInterval& ray = lanes.rays[std::size_t(lanes.count)];
    ray.origin = Vec3(RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i));
    ray.direction = Vec3(RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i));
    ray.tmin = RTCRayN_tnear(rays, n, i);
    ray.tmax = RTCRayN_tfar(rays, n, i);
    lanes.lane[std::size_t(lanes.count++)] = i;
  }
  return lanes;
}

// A typical influence diameter: windows of a few of them hold a few layers
// of sources.
double mean_influence_diagonal(const BlobField& field) {
  if (field.sources.empty()) return 1.0;
  double sum = 0.0;
  for (const BlobSource& s : field.sources) sum += influence_bounds(s).diagonal();
  return sum / double(field.sources.size());
}

}  // namespace

BlobGeometry::BlobGeometry(RTCDevice device, const BlobField& field, const TraceSettings& settings)
    : field_(field),
      settings_(settings),
      bounds_(influence_bounds(field)),
      first_window_(2.0 * mean_influence_diagonal(field)),
      rank_(spatial_ranks(field, bounds_)),
      device_(device) {
  span_scene_ = rtcNewScene(device_);
  // Up to a few hundred thousand sources the best BVH costs nothing
  // noticeable. Beyond, its build arrays dominate peak memory: Embree's
  // Morton builder (LOW) needs about 50 bytes less per source (106 against
  // 155 bytes in all at 10⁶, tests/bench/scale_bench) for about 15% more
  // render time.
  constexpr std::size_t large_field = 250000;
  rtcSetSceneBuildQuality(span_scene_, field.sources.size() > large_field ? RTC_BUILD_QUALITY_LOW
                                                                           : RTC_BUILD_QUALITY_HIGH);
  rtcSetSceneFlags(span_scene_, RTC_SCENE_FLAG_COMPACT);
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(field.sources.size()));
  rtcSetGeometryUserData(geometry, const_cast<BlobField*>(&field_));
  rtcSetGeometryBoundsFunction(geometry, span_bounds, nullptr);
  rtcSetGeometryIntersectFunction(geometry, span_intersect);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(span_scene_, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(span_scene_);
  check_device(device_, "building the span BVH");
}

BlobGeometry::~BlobGeometry() {
  if (span_scene_) rtcReleaseScene(span_scene_);
}

unsigned BlobGeometry::attach_to(RTCScene scene, unsigned mask) {
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, field_.sources.empty() ? 0u : 1u);
  rtcSetGeometryMask(geometry, mask);
  rtcSetGeometryUserData(geometry, this);
  rtcSetGeometryBoundsFunction(geometry, field_bounds, nullptr);
  rtcSetGeometryIntersectFunction(geometry, field_intersect);
  rtcSetGeometryOccludedFunction(geometry, field_occluded);
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  check_device(device_, "attaching the field geometry");
  return id;
}

void BlobGeometry::span_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* field = static_cast<const BlobField*>(args->geometryUserPtr);
  store_bounds(influence_bounds(field->sources[args->primID]), args->bounds_o);
}

void BlobGeometry::span_intersect(const RTCIntersectFunctionNArguments* args) {
  auto* query = reinterpret_cast<SpanQueryContext*>(args->context);
  const int n = int(args->N);
  if (n == 1) {  // a lone ray (rtcIntersect1): no lanes to gather
    ++query->candidates;
    const RayLanes& r = query->rays;
    RaySpan span;
    if (ray_span(query->field->sources[args->primID], args->primID, Vec3(r.ox[0], r.oy[0], r.oz[0]),
                 Vec3(r.dx[0], r.dy[0], r.dz[0]), r.tmin[0], r.tmax[0], span))
      query->tracers[0].spans.push_back(span);
    return;
  }
  unsigned valid = 0;
  for (int i = 0; i < n; ++i) valid |= unsigned(args->valid[i] != 0) << i;
  query->candidates += unsigned(__builtin_popcount(valid));
  SpanLanes spans;
  unsigned entered = valid & ray_spans(query->field->sources[args->primID], query->rays, n, spans);
  for (; entered; entered &= entered - 1) {
    const int i = __builtin_ctz(entered);
    query->tracers[i].spans.push_back(
        RaySpan{spans.t0[i], spans.t1[i], spans.a[i], spans.t_c[i], spans.g_min[i], args->primID});
  }
  // No hit is reported: traversal goes on and visits every crossed box.
}

std::size_t BlobGeometry::collect_spans(const RayInterval* rays, int count, FieldRay* tracers) const {
  if (count < 1 || count > kMaxPacket)
    throw std::invalid_argument("collect_spans takes 1 to " + std::to_string(kMaxPacket) + " rays");
  return query_spans(rays, tracers, (1u << count) - 1u);
}

std::size_t BlobGeometry::query_spans(const RayInterval* rays, FieldRay* tracers, unsigned lanes) const {
  SpanQueryContext query;
  rtcInitIntersectContext(&query.embree);
  query.field = &field_;
  query.tracers = tracers;
  query.candidates = 0;
  for (unsigned i = 0; i < unsigned(kMaxPacket); ++i)
    if (lanes & (1u << i)) tracers[i].spans.clear();

  // Widen the float interval by a hair: the spans are clipped exactly to
  // [tmin, tmax] in double by ray_spans, and Embree's float boxes must not
  // cull a source that touches the interval's ends.
  constexpr float inf = std::numeric_limits<float>::infinity();
  auto float_interval = [&](const RayInterval& ray) {
    return std::pair<float, float>(std::nextafter(float(ray.tmin), 0.0f),
                                   std::isinf(ray.tmax) ? inf : std::nextafter(float(ray.tmax), inf));
  };
  if ((lanes & (lanes - 1)) == 0) {  // one ray: a packet would only add overhead
    const int lane = __builtin_ctz(lanes);
    const RayInterval& ray = rays[lane];
    query.rays.set(0, ray.origin, ray.direction, ray.tmin, ray.tmax);
    query.tracers = tracers + lane;
    const auto [tnear, tfar] = float_interval(ray);
    RTCRayHit rayhit = make_embree_ray(ray.origin, ray.direction, tnear, tfar);
    rtcIntersect1(span_scene_, &query.embree, &rayhit);
    return query.candidates;
  }
  query.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(64) int valid[kMaxPacket];
  alignas(64) RTCRayHit16 packet{};
  for (int i = 0; i < kMaxPacket; ++i) {
    valid[i] = (lanes & (1u << i)) ? -1 : 0;
    const RayInterval& ray = valid[i] ? rays[i] : rays[__builtin_ctz(lanes)];  // idle lanes stay finite
    query.rays.set(i, ray.origin, ray.direction, ray.tmin, ray.tmax);
    if (!valid[i]) continue;
    const auto [tnear, tfar] = float_interval(ray);
    set_embree_ray(reinterpret_cast<RTCRayHitN*>(&packet), kMaxPacket, unsigned(i), ray.origin,
                   ray.direction, tnear, tfar);
  }
  rtcIntersect16(valid, span_scene_, &query.embree, &packet);
  return query.candidates;
}

void BlobGeometry::first_crossings(const RayInterval* rays, int count, FieldRay* tracers,
                                   TraceStats& stats, double* hits, CrossingQuery query) const {
  // Each window's spans are clipped to it, and they are all the sources
  // that are non-zero in it, so F there is exact. A crossing at a window's
  // end is found by that window (segment ends are evaluated). All rays of a
  // batch step through their windows together, so each step is one packet
  // query for the rays still looking.
  if (count > kMaxPacket)
    throw std::invalid_argument("first_crossings takes at most " + std::to_string(kMaxPacket) + " rays");
  std::array<RayInterval, kMaxPacket> window;
  std::array<double, kMaxPacket> t_end, length;
  unsigned looking = 0;
  for (int i = 0; i < count; ++i) {
    ++stats.field_rays;
    hits[i] = -1.0;
    const auto [t, end] = ray_interval_in(bounds_, rays[i].origin, rays[i].direction, rays[i].tmin, rays[i].tmax);
    window[i] = {rays[i].origin, rays[i].direction, t, t};
    t_end[i] = end;
    length[i] = first_window_ / rays[i].direction.norm();  // in units of t
    if (t < end) looking |= 1u << i;
  }
  while (looking) {
    for (int i = 0; i < count; ++i)
      if (looking & (1u << i)) window[i].tmax = std::min(window[i].tmin + length[i], t_end[i]);
    stats.span_queries += unsigned(__builtin_popcount(looking));
    stats.span_candidates += query_spans(window.data(), tracers, looking);
    for (int i = 0; i < count; ++i) {
      const unsigned bit = 1u << i;
      if (!(looking & bit)) continue;
      if (!tracers[i].spans.empty()) {
        const double hit = tracers[i].first_crossing(field_, window[i].tmin, window[i].tmax, settings_, stats, query);
        if (hit >= 0.0) {
          hits[i] = hit;
          looking &= ~bit;
          continue;
        }
      }
      window[i].tmin = window[i].tmax;
      length[i] *= 2.0;  // long empty stretches cost a logarithmic number of queries
      if (!(window[i].tmin < t_end[i])) looking &= ~bit;
    }
  }
}

namespace {

// The point query that gather_nearby() runs: Embree calls back for every
// source whose bounds come within the radius of the region's centre; the
// box test settles which of them meet the region.
struct NearbyQuery {
  const BlobField* field;
  Box3 region;
  std::size_t limit;
  std::vector<std::uint32_t>* found;
  bool overflow = false;
};

bool nearby_candidate(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<NearbyQuery*>(args->userPtr);
  if (q->overflow) return false;
  if (!influence_bounds(q->field->sources[args->primID]).overlaps(q->region)) return false;
  if (q->found->size() == q->limit) {
    // Too many to be worth it: shrink the query to nothing so the
    // traversal ends soon.
    q->overflow = true;
    args->query->radius = 0.0f;
    return true;
  }
  q->found->push_back(args->primID);
  return false;
}

}  // namespace

bool BlobGeometry::gather_nearby(const Box3& region, std::size_t limit, NearbySources& nearby,
                                 std::vector<std::uint32_t>& scratch) const {
  nearby.clear();
  scratch.clear();
  NearbyQuery q{&field_, region, limit, &scratch};
  const Vec3 centre = region.centre();
  RTCPointQuery query;
  query.x = float(centre.x());
  query.y = float(centre.y());
  query.z = float(centre.z());
  query.time = 0.0f;
  // The sphere around the box, a hair larger so float rounding never culls
  // a source that meets the box.
  query.radius = std::nextafter(float(0.5 * region.diagonal() * (1.0 + 1e-6)), INFINITY);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(span_scene_, &query, &context, nearby_candidate, &q);
  if (q.overflow) return false;
  // Rank order, whatever order the traversal met them in: groups of
  // neighbours for the list's boxes, and the order first_crossing_in_order()
  // puts its spans in.
  std::sort(scratch.begin(), scratch.end(), [&](std::uint32_t a, std::uint32_t b) { return rank_[a] < rank_[b]; });
  for (const std::uint32_t i : scratch) nearby.add(field_.sources[i], i);
  return true;
}

template <class CollectSpans>
double BlobGeometry::first_crossing_of(const RayInterval& ray, FieldRay& tracer, TraceStats& stats,
                                       CrossingQuery query, CollectSpans&& collect_spans) const {
  ++stats.field_rays;
  tracer.spans.clear();
  const auto [t, end] = ray_interval_in(bounds_, ray.origin, ray.direction, ray.tmin, ray.tmax);
  if (!(t < end)) return -1.0;
  collect_spans(RayInterval{ray.origin, ray.direction, t, end});
  if (tracer.spans.empty()) return -1.0;
  return tracer.first_crossing(field_, t, end, settings_, stats, query);
}

double BlobGeometry::first_crossing_near(const NearbySources& nearby, const RayInterval& ray, FieldRay& tracer,
                                         TraceStats& stats, CrossingQuery query) const {
  return first_crossing_of(ray, tracer, stats, query, [&](const RayInterval& clipped) {
    nearby.collect_spans(clipped.origin, clipped.direction, clipped.tmin, clipped.tmax, tracer.spans);
    stats.span_candidates += nearby.size();
  });
}

double BlobGeometry::first_crossing_in_order(const RayInterval& ray, FieldRay& tracer, TraceStats& stats,
                                             CrossingQuery query) const {
  return first_crossing_of(ray, tracer, stats, query, [&](const RayInterval& clipped) {
    ++stats.span_queries;
    stats.span_candidates += query_spans(&clipped, &tracer, 1u);
    std::sort(tracer.spans.begin(), tracer.spans.end(),
              [&](const RaySpan& x, const RaySpan& y) { return rank_[x.source] < rank_[y.source]; });
  });
}

void BlobGeometry::field_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* self = static_cast<const BlobGeometry*>(args->geometryUserPtr);
  store_bounds(self->bounds_, args->bounds_o);
}

void BlobGeometry::field_intersect(const RTCIntersectFunctionNArguments* args) {
  const auto* self = static_cast<const BlobGeometry*>(args->geometryUserPtr);
  auto* context = reinterpret_cast<FieldRayContext*>(args->context);
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  const ValidLanes lanes = gather_lanes(args->valid, rays, args->N);
  double t[kMaxPacket];
  self->first_crossings(lanes.rays.data(), lanes.count, context->tracers->data(), *context->stats, t);
  for (int j = 0; j < lanes.count; ++j) {
    if (t[j] < 0.0) continue;
    const unsigned i = lanes.lane[j];
    const RayInterval& ray = lanes.rays[j];
    context->t[i] = t[j];
    const SurfaceSample& surface = context->surface[i] =
        (*context->tracers)[j].surface_at(self->field_, ray.origin, ray.direction, t[j]);
    RTCRayN_tfar(rays, args->N, i) = static_cast<float>(t[j]);
    RTCHitN_Ng_x(hits, args->N, i) = static_cast<float>(surface.normal.x());
    RTCHitN_Ng_y(hits, args->N, i) = static_cast<float>(surface.normal.y());
    RTCHitN_Ng_z(hits, args->N, i) = static_cast<float>(surface.normal.z());
    RTCHitN_u(hits, args->N, i) = RTCHitN_v(hits, args->N, i) = 0.0f;
    RTCHitN_primID(hits, args->N, i) = args->primID;
    RTCHitN_geomID(hits, args->N, i) = args->geomID;
    RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
  }
}

void BlobGeometry::field_occluded(const RTCOccludedFunctionNArguments* args) {
  const auto* self = static_cast<const BlobGeometry*>(args->geometryUserPtr);
  auto* context = reinterpret_cast<FieldRayContext*>(args->context);
  const ValidLanes lanes = gather_lanes(args->valid, args->ray, args->N);
  double t[kMaxPacket];
  self->first_crossings(lanes.rays.data(), lanes.count, context->tracers->data(), *context->stats, t,
                        CrossingQuery::any);
  for (int j = 0; j < lanes.count; ++j)
    if (t[j] >= 0.0) RTCRayN_tfar(args->ray, args->N, lanes.lane[j]) = -std::numeric_limits<float>::infinity();
}

}  // namespace hsb
