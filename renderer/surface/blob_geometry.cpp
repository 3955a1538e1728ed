#include "renderer/surface/blob_geometry.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "renderer/surface/embree_ray.h"

namespace hsb {
namespace {

// The span query's context: where the span BVH's callback writes.
struct SpanQueryContext {
  RTCIntersectContext embree;  // first member, see FieldRayContext
  const BlobField* field;
  Vec3 origin, direction;
  double tmin, tmax;
  std::vector<RaySpan>* spans;
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

// The parameter interval where the ray o + t d is inside `box`, intersected
// with [tmin, tmax]; empty (lo > hi) when it misses.
std::pair<double, double> clip_to_box(const Box3& box, const Vec3& o, const Vec3& d, double tmin, double tmax) {
  double lo = tmin, hi = tmax;
  for (int k = 0; k < 3; ++k) {
    const double inv = 1.0 / d[k];  // ±inf for an axis-parallel ray: the slab test still works
    double a = (box.lo[k] - o[k]) * inv, b = (box.hi[k] - o[k]) * inv;
    if (a > b) std::swap(a, b);
    if (!(a <= b)) continue;  // NaN: the ray lies in the slab's plane
    lo = std::max(lo, a);
    hi = std::min(hi, b);
  }
  return {lo, hi};
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

unsigned BlobGeometry::attach_to(RTCScene scene) {
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, field_.sources.empty() ? 0u : 1u);
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
  if (!args->valid[0]) return;
  auto* query = reinterpret_cast<SpanQueryContext*>(args->context);
  RaySpan span;
  if (ray_span(query->field->sources[args->primID], args->primID, query->origin, query->direction,
               query->tmin, query->tmax, span))
    query->spans->push_back(span);
  // No hit is reported: traversal goes on and visits every crossed box.
}

void BlobGeometry::collect_spans(const Vec3& o, const Vec3& d, double tmin, double tmax,
                                 FieldRay& tracer) const {
  tracer.spans.clear();
  SpanQueryContext query;
  rtcInitIntersectContext(&query.embree);
  query.field = &field_;
  query.origin = o;
  query.direction = d;
  query.tmin = tmin;
  query.tmax = tmax;
  query.spans = &tracer.spans;

  // Widen the float interval by a hair: the spans are clipped exactly to
  // [tmin, tmax] in double by ray_span, and Embree's float boxes must not
  // cull a source that touches the interval's ends.
  constexpr float inf = std::numeric_limits<float>::infinity();
  RTCRayHit rayhit = make_embree_ray(o, d, std::nextafter(float(tmin), 0.0f),
                                     std::isinf(tmax) ? inf : std::nextafter(float(tmax), inf));
  rtcIntersect1(span_scene_, &query.embree, &rayhit);
}

double BlobGeometry::first_crossing(const Vec3& o, const Vec3& d, double tmin, double tmax,
                                    FieldRay& tracer, TraceStats& stats) const {
  ++stats.field_rays;
  auto [t, t_end] = clip_to_box(bounds_, o, d, tmin, tmax);
  // Each window's spans are clipped to it, and they are all the sources
  // that are non-zero in it, so F there is exact. A crossing at a window's
  // end is found by that window (segment ends are evaluated).
  double window = first_window_ / d.norm();  // a length, in units of t
  while (t < t_end) {
    const double t_next = std::min(t + window, t_end);
    collect_spans(o, d, t, t_next, tracer);
    if (!tracer.spans.empty()) {
      const double hit = tracer.first_crossing(field_, t, t_next, settings_, stats);
      if (hit >= 0.0) return hit;
    }
    t = t_next;
    window *= 2.0;  // long empty stretches cost a logarithmic number of queries
  }
  return -1.0;
}

void BlobGeometry::field_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* self = static_cast<const BlobGeometry*>(args->geometryUserPtr);
  store_bounds(self->bounds_, args->bounds_o);
}

void BlobGeometry::field_intersect(const RTCIntersectFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* self = static_cast<const BlobGeometry*>(args->geometryUserPtr);
  auto* context = reinterpret_cast<FieldRayContext*>(args->context);
  RTCRayHit* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);
  RTCRay& ray = rayhit->ray;
  const Vec3 o(ray.org_x, ray.org_y, ray.org_z);
  const Vec3 d(ray.dir_x, ray.dir_y, ray.dir_z);
  const double t = self->first_crossing(o, d, ray.tnear, ray.tfar, *context->tracer, *context->stats);
  if (t < 0.0) return;

  context->t = t;
  context->surface = context->tracer->surface_at(self->field_, o, d, t);
  ray.tfar = static_cast<float>(t);
  rayhit->hit.Ng_x = static_cast<float>(context->surface.normal.x());
  rayhit->hit.Ng_y = static_cast<float>(context->surface.normal.y());
  rayhit->hit.Ng_z = static_cast<float>(context->surface.normal.z());
  rayhit->hit.u = rayhit->hit.v = 0.0f;
  rayhit->hit.primID = args->primID;
  rayhit->hit.geomID = args->geomID;
  rayhit->hit.instID[0] = args->context->instID[0];
}

void BlobGeometry::field_occluded(const RTCOccludedFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto* self = static_cast<const BlobGeometry*>(args->geometryUserPtr);
  auto* context = reinterpret_cast<FieldRayContext*>(args->context);
  RTCRay* ray = reinterpret_cast<RTCRay*>(args->ray);
  const Vec3 o(ray->org_x, ray->org_y, ray->org_z);
  const Vec3 d(ray->dir_x, ray->dir_y, ray->dir_z);
  if (self->first_crossing(o, d, ray->tnear, ray->tfar, *context->tracer, *context->stats) >= 0.0)
    ray->tfar = -std::numeric_limits<float>::infinity();
}

}  // namespace hsb
