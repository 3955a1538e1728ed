#include "renderer/render/shell_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "base/float_steps.h"
#include "base/point_extremes.h"
#include "renderer/surface/embree_bounds.h"

namespace hsb {
namespace {

struct Hit {
  double t;
  std::uint32_t triangle;
  Vec3 weights;
};

// What the shell's callback collects: every crossing, none reported to
// Embree, so the traversal visits every triangle the ray may cross. The
// ray itself in double precision: Embree's copy is rounded to float.
struct ShellQuery {
  RTCIntersectContext embree;  // first member: Embree hands this pointer back
  const TriangleMesh* mesh;
  Vec3 origin, direction;
  double tmax;
  std::vector<Hit>* hits;
};

}  // namespace

double ray_triangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c, double tmin,
                    double tmax, Vec3& weights) {
  // Shear the ray to the +z axis: the triangle's edge functions in the
  // sheared plane decide the hit. A shared edge gives its two triangles
  // edge functions of the same products, exactly negated, so no ray
  // slips between them.
  int kz = 0;
  d.cwiseAbs().maxCoeff(&kz);
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (d[kz] < 0.0) std::swap(kx, ky);  // keep the winding
  const double sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.0 / d[kz];
  const Vec3 pa = a - o, pb = b - o, pc = c - o;
  const double ax = pa[kx] - sx * pa[kz], ay = pa[ky] - sy * pa[kz];
  const double bx = pb[kx] - sx * pb[kz], by = pb[ky] - sy * pb[kz];
  const double cx = pc[kx] - sx * pc[kz], cy = pc[ky] - sy * pc[kz];
  const double u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return -1.0;
  const double det = u + v + w;
  if (det == 0.0) return -1.0;  // seen edge-on
  const double t = (u * sz * pa[kz] + v * sz * pb[kz] + w * sz * pc[kz]) / det;
  if (!(t > tmin && t < tmax)) return -1.0;
  weights = Vec3(u, v, w) / det;
  return t;
}

ShellGeometry::ShellGeometry(RTCDevice device, const TriangleMesh& mesh) : mesh_(mesh) {
  const Box3 box = bounding_box(mesh.vertices);
  // The triangles sharing an edge or a vertex a ray passes through give
  // that crossing's t to within rounding; distinct layers of a body are
  // never this close.
  merge_distance_ = mesh.vertices.empty() ? 0.0 : 1e-9 * box.diagonal();
  margin_ = mesh.vertices.empty() ? 0.0 : bounds_margin(box.diagonal());

  scene_ = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, unsigned(mesh.triangles.size()));
  rtcSetGeometryUserData(geometry, this);
  rtcSetGeometryBoundsFunction(geometry, bounds, nullptr);
  rtcSetGeometryIntersectFunction(geometry, intersect);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device) != RTC_ERROR_NONE) throw std::runtime_error("Embree failed to build the shell");
}

ShellGeometry::~ShellGeometry() {
  if (scene_) rtcReleaseScene(scene_);
}

void ShellGeometry::bounds(const RTCBoundsFunctionArguments* args) {
  const auto* self = static_cast<const ShellGeometry*>(args->geometryUserPtr);
  const auto& tri = self->mesh_.triangles[args->primID];
  const Vec3 &a = self->mesh_.vertices[tri[0]], &b = self->mesh_.vertices[tri[1]], &c = self->mesh_.vertices[tri[2]];
  store_bounds(Box3{a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)}, self->margin_, args->bounds_o);
}

void ShellGeometry::intersect(const RTCIntersectFunctionNArguments* args) {
  auto* query = reinterpret_cast<ShellQuery*>(args->context);
  const TriangleMesh& mesh = *query->mesh;
  const auto& tri = mesh.triangles[args->primID];
  // One ray (rtcIntersect1), the query's own.
  Vec3 weights;
  const double t = ray_triangle(query->origin, query->direction, mesh.vertices[tri[0]], mesh.vertices[tri[1]],
                                mesh.vertices[tri[2]], 0.0, query->tmax, weights);
  if (t >= 0.0) query->hits->push_back({t, args->primID, weights});
  // No hit is reported: the traversal goes on to every crossing.
}

void ShellGeometry::crossings(const Vec3& o, const Vec3& d, double tmax, std::size_t max_layers,
                              std::vector<ShellCrossing>& out) const {
  out.clear();
  thread_local std::vector<Hit> hits;
  hits.clear();
  ShellQuery query{{}, &mesh_, o, d, tmax, &hits};
  rtcInitIntersectContext(&query.embree);
  RTCRayHit rayhit{};
  rayhit.ray.org_x = float(o.x()), rayhit.ray.org_y = float(o.y()), rayhit.ray.org_z = float(o.z());
  rayhit.ray.dir_x = float(d.x()), rayhit.ray.dir_y = float(d.y()), rayhit.ray.dir_z = float(d.z());
  rayhit.ray.tnear = 0.0f;
  rayhit.ray.tfar = std::isinf(tmax) ? INFINITY : float_up(float(tmax));
  rayhit.ray.mask = 0xFFFFFFFFu;
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &query.embree, &rayhit);

  // In order along the ray, ties by triangle, whatever order the BVH met them in.
  std::sort(hits.begin(), hits.end(),
            [](const Hit& x, const Hit& y) { return x.t < y.t || (x.t == y.t && x.triangle < y.triangle); });
  const double merge = merge_distance_ / d.norm();
  double last = -std::numeric_limits<double>::infinity();
  for (const Hit& hit : hits) {
    if (out.size() == max_layers || hit.t >= tmax) break;
    if (hit.t - last <= merge) continue;  // the same crossing, from a neighbouring triangle
    last = hit.t;
    const auto& tri = mesh_.triangles[hit.triangle];
    Vec3 normal = Vec3::Zero();
    if (mesh_.normals.size() == mesh_.vertices.size())
      normal = hit.weights[0] * mesh_.normals[tri[0]] + hit.weights[1] * mesh_.normals[tri[1]] +
               hit.weights[2] * mesh_.normals[tri[2]];
    if (!(normal.squaredNorm() > 0.0))  // flat shading, or normals that cancel
      normal = (mesh_.vertices[tri[1]] - mesh_.vertices[tri[0]]).cross(mesh_.vertices[tri[2]] - mesh_.vertices[tri[0]]);
    out.push_back({hit.t, normal.normalized()});
  }
}

}  // namespace hsb
