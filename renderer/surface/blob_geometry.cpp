#include "renderer/surface/blob_geometry.h"

#include "renderer/surface/embree_ray.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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

}  // namespace

BlobGeometry::BlobGeometry(RTCDevice device, const BlobField& field, const TraceSettings& settings)
    : field_(field), settings_(settings), bounds_(influence_bounds(field)), device_(device) {
  span_scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(span_scene_, RTC_BUILD_QUALITY_HIGH);
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
  collect_spans(o, d, tmin, tmax, tracer);
  if (tracer.spans.empty()) return -1.0;
  return tracer.first_crossing(field_, tmin, tmax, settings_, stats);
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
