#include "renderer/render/camera_frustum.h"

#include <algorithm>
#include <array>

namespace hsb {

bool rectangle_may_see(const Camera& camera, double x0, double y0, double x1, double y1, const Box3& box) {
  if (!(box.lo.array() <= box.hi.array()).all()) return false;
  // The corner rays in order around the rectangle, and its centre's.
  const std::array<CameraRay, 4> corner{camera.ray(x0, y0), camera.ray(x1, y0), camera.ray(x1, y1), camera.ray(x0, y1)};
  const CameraRay centre = camera.ray(0.5 * (x0 + x1), 0.5 * (y0 + y1));
  const Vec3 inside = centre.origin + centre.direction;
  const double margin = 1e-4 * std::max(box.diagonal(), (box.centre() - centre.origin).norm());
  Box3 grown = box;
  grown.lo.array() -= margin;
  grown.hi.array() += margin;
  const std::array<Vec3, 8> points = grown.corners();
  for (int side = 0; side < 4; ++side) {
    const CameraRay& a = corner[std::size_t(side)];
    const CameraRay& b = corner[std::size_t((side + 1) % 4)];
    // The plane holding both rays: a's origin and direction, and b's point
    // one unit along (b's origin is a's for a perspective camera; its
    // direction is a's for an orthographic one).
    Vec3 normal = a.direction.cross(b.origin + b.direction - a.origin);
    if (normal.squaredNorm() == 0.0) continue;  // a rectangle of no width: no side to cut by
    if (normal.dot(inside - a.origin) < 0.0) normal = -normal;
    const bool all_outside =
        std::all_of(points.begin(), points.end(), [&](const Vec3& p) { return normal.dot(p - a.origin) < 0.0; });
    if (all_outside) return false;
  }
  return true;
}

}  // namespace hsb
