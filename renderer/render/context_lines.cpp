#include "renderer/render/context_lines.h"

#include <cmath>
#include <limits>

#include "base/point_extremes.h"
#include "renderer/surface/embree_bounds.h"
#include "renderer/surface/embree_ray.h"

namespace hsb {
namespace {

// The entry into the ball of radius r around c, or a negative value.
double ray_ball(const Vec3& o, const Vec3& d, const Vec3& c, double r) {
  const Vec3 oc = o - c;
  const double dd = d.squaredNorm(), half_b = d.dot(oc);
  const double disc = half_b * half_b - dd * (oc.squaredNorm() - r * r);
  if (disc < 0.0 || dd == 0.0) return -1.0;
  return (-half_b - std::sqrt(disc)) / dd;
}

}  // namespace

double ray_capsule(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, double r, double tmin, double tmax,
                   Vec3& normal) {
  // The capsule is the union of the balls at its ends and the cylinder
  // between them, so its first entry is the earliest entry into any of the
  // three (a ray entering the cylinder through an end disc is already in
  // that end's ball).
  double best = -1.0;
  Vec3 centre = Vec3::Zero();  // the normal points from here, or from the axis
  const auto consider = [&](double t, const Vec3& from) {
    if (t >= tmin && t <= tmax && (best < 0.0 || t < best)) best = t, centre = from;
  };
  const Vec3 ba = b - a, oa = o - a;
  const double baba = ba.squaredNorm();
  // The infinite cylinder: |(p − a) × ba|² = r²|ba|² along p = o + t d, by
  // Lagrange's identity in cross products, which stay accurate for a
  // distant camera where dot products would cancel.
  const Vec3 u = d.cross(ba), w = oa.cross(ba);
  const double qa = u.squaredNorm(), qb = u.dot(w), qc = w.squaredNorm() - r * r * baba;
  const double disc = qb * qb - qa * qc;
  if (qa > 0.0 && disc >= 0.0) {
    const double t = (-qb - std::sqrt(disc)) / qa;
    const double y = ba.dot(oa + t * d);  // along the axis, in units of 1/|ba|
    if (y > 0.0 && y < baba) consider(t, a + (y / baba) * ba);
  }
  consider(ray_ball(o, d, a, r), a);
  consider(ray_ball(o, d, b, r), b);
  if (best >= 0.0) normal = (o + best * d - centre).normalized();
  return best;
}

ContextLines::ContextLines(const std::vector<const std::vector<Vec3>*>& lines, double radius) : radius_(radius) {
  Box3 all = bounding_box({});
  for (const std::vector<Vec3>* line : lines) {
    if (line->size() < 2) continue;
    for (std::size_t k = 1; k < line->size(); ++k) segments_.push_back({(*line)[k - 1], (*line)[k]});
    all.extend(bounding_box(*line));
  }
  margin_ = segments_.empty() ? 0.0 : bounds_margin(all.diagonal() + 2.0 * radius);
}

unsigned ContextLines::attach_to(RTCDevice device, RTCScene scene, unsigned mask) const {
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, unsigned(segments_.size()));
  rtcSetGeometryUserData(geometry, const_cast<ContextLines*>(this));
  rtcSetGeometryBoundsFunction(geometry, bounds, nullptr);
  rtcSetGeometryIntersectFunction(geometry, intersect);
  rtcSetGeometryOccludedFunction(geometry, occluded);
  rtcSetGeometryMask(geometry, mask);
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  return id;
}

void ContextLines::bounds(const RTCBoundsFunctionArguments* args) {
  const auto* self = static_cast<const ContextLines*>(args->geometryUserPtr);
  const Segment& s = self->segments_[args->primID];
  const Vec3 reach = Vec3::Constant(self->radius_);
  store_bounds(Box3{s.a.cwiseMin(s.b) - reach, s.a.cwiseMax(s.b) + reach}, self->margin_, args->bounds_o);
}

void ContextLines::intersect(const RTCIntersectFunctionNArguments* args) {
  const auto* self = static_cast<const ContextLines*>(args->geometryUserPtr);
  const Segment& s = self->segments_[args->primID];
  const unsigned n = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, n);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, n);
  for (unsigned i = 0; i < n; ++i) {
    if (!args->valid[i]) continue;
    Vec3 normal;
    const double t = ray_capsule(embree_ray_origin(rays, n, i), embree_ray_direction(rays, n, i), s.a, s.b,
                                 self->radius_, RTCRayN_tnear(rays, n, i), RTCRayN_tfar(rays, n, i), normal);
    if (t < 0.0 || !(float(t) < RTCRayN_tfar(rays, n, i))) continue;
    RTCRayN_tfar(rays, n, i) = float(t);
    RTCHitN_Ng_x(hits, n, i) = float(normal.x());
    RTCHitN_Ng_y(hits, n, i) = float(normal.y());
    RTCHitN_Ng_z(hits, n, i) = float(normal.z());
    RTCHitN_u(hits, n, i) = RTCHitN_v(hits, n, i) = 0.0f;
    RTCHitN_primID(hits, n, i) = args->primID;
    RTCHitN_geomID(hits, n, i) = args->geomID;
    RTCHitN_instID(hits, n, i, 0) = args->context->instID[0];
  }
}

void ContextLines::occluded(const RTCOccludedFunctionNArguments* args) {
  const auto* self = static_cast<const ContextLines*>(args->geometryUserPtr);
  const Segment& s = self->segments_[args->primID];
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (!args->valid[i]) continue;
    Vec3 normal;
    if (ray_capsule(embree_ray_origin(args->ray, n, i), embree_ray_direction(args->ray, n, i), s.a, s.b, self->radius_, RTCRayN_tnear(args->ray, n, i), RTCRayN_tfar(args->ray, n, i),
                    normal) >= 0.0)
      RTCRayN_tfar(args->ray, n, i) = -std::numeric_limits<float>::infinity();
  }
}

}  // namespace hsb
