#include "renderer/surface/blob_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "base/float_steps.h"
#include "renderer/surface/embree_bounds.h"
#include "renderer/surface/embree_ray.h"
#include "renderer/surface/ray_packets.h"
#include "renderer/surface/single_source.h"
#include "renderer/surface/spatial_rank.h"
#include "renderer/surface/superquadric_gauge.h"

namespace hsb {
namespace {

// The span query's context: where the span BVH's callback writes. The
// query's ray k (its Embree id) is lane k of `rays`, and its spans go to
// tracers[k].
struct SpanQueryContext {
  RTCIntersectContext embree;  // first member, see FieldRayContext
  const BlobField* field;
  // The span kernel for the field's shape under the active instruction set.
  SpanKernels::RaySpans ray_spans;
  RayLanes rays;
  FieldRay* tracers;
  std::size_t candidates;
  // A span that enters its source's own level surface K = C (for a shape
  // other than the ellipsoid, the ball inside it: ListedSource::g_inner,
  // single_source.h) ends the search beyond that point. An `any` query
  // (shadow rays): one such entry is the answer, and the traversal ends
  // there.
  bool stop_at_entry;
};

// A source whose own level surface ray k enters at t bounds the first
// crossing from above (single_source.h): F ≥ C there whatever the others
// add, and every source non-zero at or before t has an influence box the
// ray enters at or before t. So the query's ray is shortened to t (rounded
// up to the next float, as the window's own end is) and Embree visits no
// box beyond it: a ray through a pile of glyphs collects the sources in
// front of its first hit, not all it passes behind. `g_inner` is the
// source's level of g_e (inner_level_g).
void prune_beyond_entry(const SpanQueryContext& query, const RaySpan& span, double g_inner, unsigned k, RTCRayN* rays,
                        unsigned n, unsigned lane) {
  const double t = single_source_entry(span, g_inner, query.rays.tmin[k], query.rays.tmax[k]);
  if (t < 0.0) return;
  constexpr float inf = std::numeric_limits<float>::infinity();
  float& tfar = RTCRayN_tfar(rays, n, lane);
  tfar = query.stop_at_entry ? -inf : std::min(tfar, float_up(float(t)));
}

// The lanes [first, first + count) of `spans` whose closest approach lies
// inside g_e = g_inner, as bits from bit 0: only those can enter their
// source's level surface. Most spans pass wide of it; this settles them
// all at once from the lanes as the span kernel left them, where reading
// each one back after it is stored stalled on the store.
unsigned lanes_reaching(const SpanLanes& spans, int first, int count, double g_inner) {
  unsigned bits = 0;
  for (int i = 0; i < count; ++i) bits |= unsigned(spans.g_min[first + i] < g_inner) << i;
  return bits;
}

void check_device(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree error ") + std::to_string(int(error)) + " while " +
                             what);
}

// The caller's index of the ray in lane i of a callback's packet of n
// (ray_packets.h). Every query on these scenes numbers its rays below
// kMaxPacket; anything else is a bug that would write past per-ray slots.
// (An exception must not cross Embree's C frames, hence the abort.)
unsigned checked_ray_index(RTCRayN* rays, unsigned n, unsigned i) {
  const unsigned index = ray_index(rays, n, i);
  if (n > unsigned(kMaxPacket) || index >= unsigned(kMaxPacket)) {
    std::fprintf(stderr, "hsb: internal error: ray %u of a %u-ray packet reached the field geometry\n", index, n);
    std::abort();
  }
  return index;
}

// The active lanes of a callback's ray packet, gathered in lane order, with
// the caller's index of each.
struct ValidLanes {
  int count = 0;
  std::array<RayInterval, kMaxPacket> rays;
  std::array<unsigned, kMaxPacket> lane;   // in the callback's packet
  std::array<unsigned, kMaxPacket> index;  // the caller's
};

ValidLanes gather_lanes(const int* valid, RTCRayN* rays, unsigned n) {
  ValidLanes lanes;
  for (unsigned i = 0; i < n; ++i) {
    if (!valid[i]) continue;
    const std::size_t j = std::size_t(lanes.count++);
    lanes.index[j] = checked_ray_index(rays, n, i);
    lanes.lane[j] = i;
    RayInterval& ray = lanes.rays[j];
    ray.origin = embree_ray_origin(rays, n, i);
    ray.direction = embree_ray_direction(rays, n, i);
    ray.tmin = RTCRayN_tnear(rays, n, i);
    ray.tmax = RTCRayN_tfar(rays, n, i);
  }
  return lanes;
}

// The gauges that the rays `waiting` (bits) wait on. A ray that asks for
// a batch's worth or more (in a crowd) fills its own batches, and takes
// them alone: copying its glyphs in and out would cost and save nothing.
// The others, mostly two or three glyphs a probe, share batches: one
// costs little more full than part empty (superquadric_gauge.h). Every
// lane gives a glyph alone's bits, so each ray's answers are those it
// gets alone.
void evaluate_gauges_together(GlyphShape shape, FieldRay* tracers, unsigned waiting) {
  unsigned sharing = 0;
  for (unsigned rest = waiting; rest; rest &= rest - 1) {
    FieldRay& ray = tracers[__builtin_ctz(rest)];
    if (ray.gauge_count() >= std::size_t(kGaugeLanes)) ray.evaluate_gauges();
    else sharing |= rest & -rest;
  }
  if (!(sharing & (sharing - 1))) {
    if (sharing) tracers[__builtin_ctz(sharing)].evaluate_gauges();
    return;
  }
  // Kept per thread, as the tracers are: the loop never allocates once
  // they have grown.
  thread_local std::vector<ShapeSample> samples;
  thread_local std::vector<double> u, rates;
  samples.clear();
  for (unsigned rest = sharing; rest; rest &= rest - 1) {
    const FieldRay& ray = tracers[__builtin_ctz(rest)];
    samples.insert(samples.end(), ray.gauge_samples(), ray.gauge_samples() + ray.gauge_count());
  }
  u.resize(samples.size());
  rates.resize(samples.size());
  shape_u_rates(shape, samples.data(), int(samples.size()), u.data(), rates.data());
  std::size_t first = 0;
  for (unsigned rest = sharing; rest; rest &= rest - 1) {
    FieldRay& ray = tracers[__builtin_ctz(rest)];
    const std::size_t count = ray.gauge_count();
    std::copy_n(u.data() + first, count, ray.gauge_u());
    std::copy_n(rates.data() + first, count, ray.gauge_rates());
    first += count;
  }
}

// The walks of the rays `walking` (bits; FieldRay::start_crossing() said
// they wait on gauges) side by side, each round the gauges all of them
// wait on in one batch, until each has its answer: settle(i, t).
template <class Settle>
void walk_together(GlyphShape shape, FieldRay* tracers, unsigned walking, Settle&& settle) {
  while (walking) {
    evaluate_gauges_together(shape, tracers, walking);
    for (unsigned rest = walking; rest; rest &= rest - 1) {
      const int i = __builtin_ctz(rest);
      if (tracers[i].resume_crossing()) continue;
      walking &= ~(1u << i);
      settle(i, tracers[i].crossing());
    }
  }
}

// A typical influence diameter: windows of a few of them hold a few layers
// of sources.
double mean_influence_diagonal(const BlobField& field) {
  if (field.sources.empty()) return 1.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < field.sources.size(); ++i) sum += influence_bounds(field, i).diagonal();
  return sum / double(field.sources.size());
}

}  // namespace

std::vector<BlobGeometry::ListedSource> BlobGeometry::listed_sources(const BlobField& field,
                                                                     const std::vector<std::uint32_t>& ranks) {
  const double g_level = level_g(field.kernel, field.isovalue);
  std::vector<ListedSource> listed(field.sources.size());
  for (std::size_t i = 0; i < listed.size(); ++i)
    listed[i] = {influence_bounds(field, i), source_support(field, i), inner_level_g(field, std::uint32_t(i), g_level),
                 ranks[i]};
  return listed;
}

BlobGeometry::BlobGeometry(RTCDevice device, const BlobField& field, const TraceSettings& settings)
    : field_(field),
      settings_(settings),
      bounds_(influence_bounds(field)),
      margin_(bounds_margin(bounds_.diagonal())),
      // A union's query stops at the first source it enters
      // (prune_beyond_entry) and what lies in front of that is all it
      // needs: one window, the whole ray. A blend's windows keep it from
      // collecting the crowd behind its first crossing.
      first_window_(field.blend == Blend::max ? std::numeric_limits<double>::infinity()
                                              : 2.0 * mean_influence_diagonal(field)),
      listed_scale_(field.blend == Blend::max ? kernel_level_radius(field.kernel, field.isovalue) : 1.0),
      listed_(listed_sources(field, spatial_ranks(field, bounds_))),
      device_(device),
      packet_width_(native_packet_width(device)) {
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
  rtcSetGeometryUserData(geometry, this);
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
  const auto* self = static_cast<const BlobGeometry*>(args->geometryUserPtr);
  store_bounds(self->listed_bounds(args->primID), self->margin_, args->bounds_o);
}

Box3 BlobGeometry::listed_bounds(std::size_t i) const {
  const Box3& influence = listed_[i].influence;
  if (listed_scale_ == 1.0) return influence;
  const BlobSource& s = field_.sources[i];
  const Vec3 centre(s.centre[0], s.centre[1], s.centre[2]);
  return {centre + listed_scale_ * (influence.lo - centre), centre + listed_scale_ * (influence.hi - centre)};
}

void BlobGeometry::span_intersect(const RTCIntersectFunctionNArguments* args) {
  const auto* self = static_cast<const BlobGeometry*>(args->geometryUserPtr);
  auto* query = reinterpret_cast<SpanQueryContext*>(args->context);
  const unsigned n = args->N;
  RTCRayN* embree_rays = RTCRayHitN_RayN(args->rayhit, n);
  const BlobSource& source = query->field->sources[args->primID];
  const ListedSource& listed = self->listed_[args->primID];
  const ShapeSupport& support = listed.support;
  const double g_inner = listed.g_inner;
  const std::uint32_t rank = listed.rank;
  const RayLanes& r = query->rays;
  if (n == 1) {  // a lone ray (rtcIntersect1): no lanes to gather
    ++query->candidates;
    const unsigned k = checked_ray_index(embree_rays, 1, 0);
    RaySpan span;
    const Vec3 o = r.origin(int(k)), d = r.direction(int(k));
    if (ray_span(source, args->primID, rank, o, d, r.tmin[k], r.tmax[k], span, support) &&
        narrow_to_influence(query->field->shape, listed.influence, o, d, span)) {
      query->tracers[k].spans.push_back(span);
      if (span.g_min < g_inner) prune_beyond_entry(*query, span, g_inner, k, embree_rays, 1, 0);
    }
    return;
  }
  // Which of the query's rays each lane holds. A packet issued at the
  // device's width reaches here whole, lane i holding ray first + i, and
  // the query's own lanes serve as they are; any other arrangement is
  // gathered into lanes [0, n) first.
  unsigned valid = 0, candidates = 0;
  std::array<unsigned, kMaxPacket> index;
  for (unsigned i = 0; i < n; ++i) {
    if (!args->valid[i]) continue;
    valid |= 1u << i;
    ++candidates;  // (a popcount is a library call without -mpopcnt)
    index[i] = checked_ray_index(embree_rays, n, i);
  }
  if (!valid) return;
  query->candidates += candidates;
  const unsigned lowest = unsigned(__builtin_ctz(valid));
  const int first = int(index[lowest]) - int(lowest);
  bool in_place = first >= 0 && first + int(n) <= kMaxPacket;
  for (unsigned rest = valid; rest && in_place; rest &= rest - 1) {
    const unsigned i = unsigned(__builtin_ctz(rest));
    in_place = index[i] == unsigned(first) + i;
  }
  // Lane i of the packet is lane i + offset of the spans computed.
  SpanLanes spans;
  unsigned entered;
  int offset;
  if (in_place) {
    entered = (query->ray_spans(source, support, r, first, int(n), spans) >> first) & valid;
    offset = first;
  } else {
    RayLanes gathered;
    for (unsigned i = 0; i < n; ++i) {
      const unsigned k = valid & (1u << i) ? index[i] : index[lowest];  // idle lanes repeat a real ray
      gathered.set(int(i), r.origin(int(k)), r.direction(int(k)), r.tmin[k], r.tmax[k]);
    }
    entered = query->ray_spans(source, support, gathered, 0, int(n), spans) & valid;
    offset = 0;
  }
  const GlyphShape shape = query->field->shape;
  const unsigned reaching = lanes_reaching(spans, offset, int(n), g_inner);
  for (unsigned rest = entered; rest; rest &= rest - 1) {
    const unsigned i = unsigned(__builtin_ctz(rest));
    const unsigned k = index[i];
    std::vector<RaySpan>& list = query->tracers[k].spans;
    spans.append(int(i) + offset, args->primID, rank, list);
    if (!narrow_to_influence(shape, listed.influence, r.origin(int(k)), r.direction(int(k)), list.back())) {
      list.pop_back();
      continue;
    }
    if (reaching & (1u << i)) prune_beyond_entry(*query, list.back(), g_inner, k, embree_rays, n, i);
  }
  // No hit is reported: traversal goes on and visits every crossed box it
  // has not pruned.
}

std::size_t BlobGeometry::collect_spans(const RayInterval* rays, int count, FieldRay* tracers) const {
  if (count < 1 || count > kMaxPacket)
    throw std::invalid_argument("collect_spans takes 1 to " + std::to_string(kMaxPacket) + " rays");
  return query_spans(rays, tracers, (1u << count) - 1u);
}

std::size_t BlobGeometry::query_spans(const RayInterval* rays, FieldRay* tracers, unsigned lanes,
                                      CrossingQuery crossing) const {
  SpanQueryContext query;
  rtcInitIntersectContext(&query.embree);
  query.field = &field_;
  const SpanKernels& kernels = span_kernels(active_isa());
  query.ray_spans = kernels.for_shape(field_.shape);
  query.tracers = tracers;
  query.candidates = 0;
  query.stop_at_entry = crossing == CrossingQuery::any;
  // Ray i of the query is lane i of `rays` and has Embree id i. For a
  // packet, idle lanes repeat an asked ray so the SIMD lanes stay finite.
  const bool alone = (lanes & (lanes - 1)) == 0;
  for (int i = 0; i < kMaxPacket; ++i) {
    const bool asked = lanes & (1u << i);
    if (!asked && alone) continue;
    const RayInterval& ray = asked ? rays[i] : rays[__builtin_ctz(lanes)];
    query.rays.set(i, ray.origin, ray.direction, ray.tmin, ray.tmax);
    if (asked) tracers[i].spans.clear();
  }
  // Widen the float interval by a hair: the spans are clipped exactly to
  // [tmin, tmax] in double by ray_spans, and Embree's float boxes must not
  // cull a source that touches the interval's ends.
  constexpr float inf = std::numeric_limits<float>::infinity();
  const auto set = [&](RTCRayHitN* packet, unsigned width, unsigned lane, int i) {
    const RayInterval& ray = rays[i];
    set_embree_ray(packet, width, lane, unsigned(i), ray.origin, ray.direction, float_toward_zero(float(ray.tmin)),
                   std::isinf(ray.tmax) ? inf : float_up(float(ray.tmax)));
  };
  // A lone ray goes alone: a packet would only add overhead.
  const int width = alone ? 1 : packet_width_;
  if (width > 1) query.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  intersect_rays(span_scene_, &query.embree, width, lanes, set, [](RTCRayHitN*, unsigned, unsigned, int) {});
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
  // A ray's crossing in its window, or none there: on to the next.
  const auto settle = [&](int i, double hit) {
    const unsigned bit = 1u << i;
    if (hit >= 0.0) {
      hits[i] = hit;
      looking &= ~bit;
      return;
    }
    window[i].tmin = window[i].tmax;
    length[i] *= 2.0;  // long empty stretches cost a logarithmic number of queries
    if (!(window[i].tmin < t_end[i])) looking &= ~bit;
  };
  while (looking) {
    for (int i = 0; i < count; ++i)
      if (looking & (1u << i)) window[i].tmax = std::min(window[i].tmin + length[i], t_end[i]);
    stats.span_queries += unsigned(__builtin_popcount(looking));
    stats.span_candidates += query_spans(window.data(), tracers, looking, query);
    unsigned walking = 0;
    for (int i = 0; i < count; ++i) {
      if (!(looking & (1u << i))) continue;
      if (tracers[i].spans.empty()) settle(i, -1.0);
      else if (tracers[i].start_crossing(field_, window[i].origin, window[i].direction, window[i].tmin,
                                         window[i].tmax, settings_, stats, query))
        walking |= 1u << i;
      else settle(i, tracers[i].crossing());
    }
    walk_together(field_.shape, tracers, walking, settle);
  }
}

namespace {

// The point query that gather_nearby() runs: Embree calls back for every
// source whose bounds come within the radius of the region's centre; the
// box test settles which of them meet the region.
struct NearbyQuery {
  const BlobGeometry* geometry;
  Box3 region;
  std::size_t limit;
  std::vector<std::uint32_t>* found;
  bool overflow = false;
};

bool nearby_candidate(RTCPointQueryFunctionArguments* args) {
  auto* q = static_cast<NearbyQuery*>(args->userPtr);
  if (q->overflow) return false;
  if (!q->geometry->listed_bounds(args->primID).overlaps(q->region)) return false;
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
  if (!region.lo.allFinite() || !region.hi.allFinite()) return false;  // the rays' own checks say why
  NearbyQuery q{this, region, limit, &scratch};
  const Vec3 centre = region.centre();
  RTCPointQuery query;
  query.x = float(centre.x());
  query.y = float(centre.y());
  query.z = float(centre.z());
  query.time = 0.0f;
  // The sphere around the box, a hair larger so float rounding never culls
  // a source that meets the box.
  query.radius = float_up(float(0.5 * region.diagonal() * (1.0 + 1e-6)));
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(span_scene_, &query, &context, nearby_candidate, &q);
  if (q.overflow) return false;
  // Rank order, whatever order the traversal met them in: groups of
  // neighbours for the list's boxes.
  std::sort(scratch.begin(), scratch.end(),
            [&](std::uint32_t a, std::uint32_t b) { return listed_[a].rank < listed_[b].rank; });
  for (const std::uint32_t i : scratch) nearby.add(field_, i, listed_[i].rank, listed_[i].influence);
  return true;
}

template <class CollectSpans>
bool BlobGeometry::start_crossing_of(const RayInterval& ray, FieldRay& tracer, TraceStats& stats, CrossingQuery query,
                                     CollectSpans&& collect_spans, double& hit) const {
  ++stats.field_rays;
  tracer.spans.clear();
  hit = -1.0;
  if (!embree_can_trace(ray.origin, ray.direction, ray.tmin, ray.tmax)) {
    ++stats.untraceable_rays;
    return false;
  }
  const auto [t, end] = ray_interval_in(bounds_, ray.origin, ray.direction, ray.tmin, ray.tmax);
  if (!(t < end)) return false;
  collect_spans(RayInterval{ray.origin, ray.direction, t, end});
  if (tracer.spans.empty()) return false;
  if (tracer.start_crossing(field_, ray.origin, ray.direction, t, end, settings_, stats, query)) return true;
  hit = tracer.crossing();
  return false;
}

void BlobGeometry::crossings_one_by_one(const RayInterval* rays, int count, const NearbySources* nearby,
                                        FieldRay* tracers, TraceStats& stats, double* hits,
                                        CrossingQuery query) const {
  if (count > kMaxPacket)
    throw std::invalid_argument("crossings_one_by_one takes at most " + std::to_string(kMaxPacket) + " rays");
  unsigned walking = 0;
  for (int i = 0; i < count; ++i) {
    FieldRay& tracer = tracers[i];
    const auto collect = [&](const RayInterval& clipped) {
      if (nearby) {
        nearby->collect_spans(clipped.origin, clipped.direction, clipped.tmin, clipped.tmax, tracer.spans);
        stats.span_candidates += nearby->size();
      } else {
        ++stats.span_queries;
        stats.span_candidates += query_spans(&clipped, &tracer, 1u, query);
      }
    };
    if (start_crossing_of(rays[i], tracer, stats, query, collect, hits[i])) walking |= 1u << i;
  }
  walk_together(field_.shape, tracers, walking, [&](int i, double hit) { hits[i] = hit; });
}

double BlobGeometry::first_crossing_near(const NearbySources& nearby, const RayInterval& ray, FieldRay& tracer,
                                         TraceStats& stats, CrossingQuery query) const {
  double hit;
  crossings_one_by_one(&ray, 1, &nearby, &tracer, stats, &hit, query);
  return hit;
}

double BlobGeometry::first_crossing_traversed(const RayInterval& ray, FieldRay& tracer, TraceStats& stats,
                                             CrossingQuery query) const {
  double hit;
  crossings_one_by_one(&ray, 1, nullptr, &tracer, stats, &hit, query);
  return hit;
}

void BlobGeometry::field_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* self = static_cast<const BlobGeometry*>(args->geometryUserPtr);
  store_bounds(self->bounds_, self->margin_, args->bounds_o);
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
    const unsigned i = lanes.lane[j], k = lanes.index[j];
    const RayInterval& ray = lanes.rays[j];
    context->t[k] = t[j];
    const SurfaceSample& surface = context->surface[k] = (*context->tracers)[j].surface_at(
        self->field_, ray.origin, ray.direction, t[j], context->hit_planes ? &context->hit_planes[k] : nullptr);
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
  FieldRay* tracers = context->tracers->data();
  for (int j = 0; j < lanes.count; ++j) tracers[j].leave_surface(context->origin_planes[lanes.index[j]]);
  double t[kMaxPacket];
  self->first_crossings(lanes.rays.data(), lanes.count, tracers, *context->stats, t, CrossingQuery::any);
  for (int j = 0; j < lanes.count; ++j)
    if (t[j] >= 0.0) RTCRayN_tfar(args->ray, args->N, lanes.lane[j]) = -std::numeric_limits<float>::infinity();
}

}  // namespace hsb
