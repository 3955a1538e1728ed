#include "renderer/render/camera_framing.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hsb {
namespace {

struct NamedView {
  const char* name;
  Vec3 direction;  // from the scene towards the camera
};

const std::array<NamedView, 7>& views() {
  static const std::array<NamedView, 7> table{{
      {"iso", Vec3(1, -1, 1).normalized()},
      {"front", Vec3(0, -1, 0)},
      {"back", Vec3(0, 1, 0)},
      {"left", Vec3(-1, 0, 0)},
      {"right", Vec3(1, 0, 0)},
      {"top", Vec3(0, 0, 1)},
      {"bottom", Vec3(0, 0, -1)},
  }};
  return table;
}


}  // namespace

std::optional<Vec3> named_view(const std::string& name) {
  for (const NamedView& v : views())
    if (name == v.name) return v.direction;
  return std::nullopt;
}

const char* const* view_names() {
  static const char* const names[] = {"iso", "front", "back", "left", "right", "top", "bottom", nullptr};
  return names;
}

Vec3 automatic_up(const Vec3& view) {
  return std::fabs(view.normalized().z()) > 0.9 ? Vec3::UnitY() : Vec3::UnitZ();
}

Vec3 automatic_view(const Box3& data, std::optional<int> plane_axis) {
  if (plane_axis) return Vec3::Unit(*plane_axis);
  const Vec3 size = data.size();
  Eigen::Index longest = 0;
  size.maxCoeff(&longest);
  Vec3 rest = size;
  rest[longest] = 0.0;
  // A compact body from the front-right, 23° above: lower than "iso", so
  // what stands on the top face is seen against the body, not the floor.
  const Vec3 front_right(0.95, -1.45, 0.75);
  // A flat body (a plate, a shell) from the side its faces look to, 15°
  // off square so the glyphs keep their relief: seen from the compact
  // view a plate is a sliver, its hole an ellipse 3:1, its glyphs a crowd.
  Eigen::Index thinnest = 0;
  size.minCoeff(&thinnest);
  Vec3 others = size;
  others[thinnest] = 0.0;
  const double middle = others.sum() - others.maxCoeff();
  if (size[thinnest] < 0.2 * middle) {
    Vec3 view = 0.16 * front_right;
    view[thinnest] = front_right[thinnest] > 0.0 ? 1.0 : -1.0;
    return view.normalized();
  }
  if (!(size[longest] > 2.0 * rest.maxCoeff())) return front_right.normalized();
  // Looking across the long axis: from −y when it is x, from +x when it
  // is y; a tall body is seen from the front-right, not much from above.
  switch (longest) {
    case 0: return Vec3(0.35, -1.0, 0.6).normalized();
    case 1: return Vec3(1.0, 0.35, 0.6).normalized();
    default: return Vec3(1.0, -1.0, 0.35).normalized();
  }
}

CameraSpec frame_camera(const CameraRequest& request, const Box3& framed, int width, int height,
                        const PictureReserve& reserve) {
  const std::array<Vec3, 8> c = framed.corners();
  return frame_camera(request, std::vector<Vec3>(c.begin(), c.end()), width, height, reserve);
}

CameraSpec frame_camera(const CameraRequest& request, const std::vector<Vec3>& framed_points, int width, int height,
                        const PictureReserve& reserve) {
  // Something to frame even when nothing is drawn: a unit box's corners.
  Box3 box = bounding_box(framed_points);
  std::array<Vec3, 8> stand_in;
  const bool nothing = !(box.diagonal() > 0.0) || !box.lo.allFinite() || !box.hi.allFinite();
  if (nothing) {
    const Vec3 c = box.centre().allFinite() ? box.centre() : Vec3::Zero();
    box = {c - Vec3::Constant(0.5), c + Vec3::Constant(0.5)};
    stand_in = box.corners();
  }
  // Every finite point, where they stand: a glyph field's are 14 a glyph
  // (11 MB for 33,768), which a copy would take again from the system.
  const auto each_point = [&](auto&& use) {
    if (nothing) {
      for (const Vec3& p : stand_in) use(p);
      return;
    }
    for (const Vec3& p : framed_points)
      if (p.allFinite()) use(p);
  };
  CameraSpec camera;
  camera.projection = request.projection;
  camera.fov_degrees = request.fov_degrees;

  Vec3 view = request.view.value_or(*named_view("iso")).normalized();
  if (request.position) {
    const Vec3 target = request.look_at.value_or(box.centre());
    if ((*request.position - target).norm() > 0.0) view = (*request.position - target).normalized();
  }
  camera.up = request.up.value_or(automatic_up(view));
  const Vec3 forward = -view;
  const Vec3 right = forward.cross(camera.up).normalized();
  const Vec3 up = right.cross(forward);
  const bool recentre = !request.look_at;
  Vec3 target = request.look_at.value_or(box.centre());

  // The camera describes the free part of the picture, the frame (its
  // top-left part); the legend's place extends the same view. The window
  // is the frame less the margin, in the frame's own coordinates: x from
  // −1 (left) to 1 (right), y from −1 (bottom) to 1.
  camera.frame_width = 1.0 - std::clamp(reserve.right, 0.0, 0.4);
  camera.frame_height = 1.0 - std::clamp(reserve.bottom, 0.0, 0.4);
  const double u_lo = -1.0 + 2.0 * request.margin, u_hi = -u_lo, v_lo = u_lo, v_hi = u_hi;
  const double aspect = camera.frame_width * double(width) / (camera.frame_height * double(height));

  if (camera.projection == Projection::orthographic) {
    double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
    each_point([&](const Vec3& p) {
      x_lo = std::min(x_lo, (p - target).dot(right)), x_hi = std::max(x_hi, (p - target).dot(right));
      y_lo = std::min(y_lo, (p - target).dot(up)), y_hi = std::max(y_hi, (p - target).dot(up));
    });
    // The view's half-height h: the window is [u_lo, u_hi]·h·aspect by
    // [v_lo, v_hi]·h in the view plane.
    double half;
    if (recentre) {
      half = std::max((x_hi - x_lo) / ((u_hi - u_lo) * aspect), (y_hi - y_lo) / (v_hi - v_lo));
      // Put the box's middle at the window's middle.
      target += (0.5 * (x_lo + x_hi) - 0.5 * (u_lo + u_hi) * half * aspect) * right +
                (0.5 * (y_lo + y_hi) - 0.5 * (v_lo + v_hi) * half) * up;
    } else {
      half = std::max({x_hi / (u_hi * aspect), x_lo / (u_lo * aspect), y_hi / v_hi, y_lo / v_lo});
    }
    camera.height = request.height.value_or(2.0 * half);
    camera.look_at = target;
    // In front of everything: rays start on the plane through the position.
    camera.position =
        request.position.value_or(target - forward * (box.diagonal() + (target - box.centre()).norm()));
    return camera;
  }

  camera.look_at = target;
  if (request.position) {
    camera.position = *request.position;
    return camera;
  }
  // The window as tangents of the angle from the view axis.
  const double tan_y = std::tan(0.5 * request.fov_degrees * M_PI / 180.0), tan_x = tan_y * aspect;
  const double x_lo = u_lo * tan_x, x_hi = u_hi * tan_x, y_lo = v_lo * tan_y, y_hi = v_hi * tan_y;
  const double clearance = 1e-3 * box.diagonal();

  // Corners in the camera's frame about the target: r along `right`, u
  // along `up`, f along `forward`; the camera stands at (P_r, P_u, P_f).
  const auto each_corner = [&](auto&& use) {
    each_point([&](const Vec3& p) {
      const Vec3 q = p - target;
      use(Vec3(q.dot(right), q.dot(up), q.dot(forward)));
    });
  };
  // Each bound below is a least or largest value over all the points, so
  // those that need nothing but the points share one pass over them (a
  // glyph field frames 14 points a glyph: 1.7 million for Teem's helix).
  double p_f = INFINITY;
  double p_r = 0.0, p_u = 0.0;
  if (recentre) {
    // Corner i is seen at (c_r − P_r)/(c_f − P_f) ∈ [lo, hi]: linear in P.
    // A P_r exists for every corner at once while, for all pairs i, j,
    // c_r,i − hi (c_f,i − P_f) ≤ c_r,j − lo (c_f,j − P_f): a bound on P_f.
    // The largest P_f fits the box as closely as the window allows; P_r
    // and P_u then take the middle of what stays possible, centring it.
    // The minimum over pairs separates: min over j of (c_j − lo f_j) less
    // the max over i of (c_i − hi f_i), so many points cost no more than
    // a few.
    double min_r = INFINITY, max_r = -INFINITY, min_u = INFINITY, max_u = -INFINITY;
    each_corner([&](const Vec3& p) {
      p_f = std::min(p_f, p.z() - clearance);
      min_r = std::min(min_r, p.x() - x_lo * p.z());
      max_r = std::max(max_r, p.x() - x_hi * p.z());
      min_u = std::min(min_u, p.y() - y_lo * p.z());
      max_u = std::max(max_u, p.y() - y_hi * p.z());
    });
    p_f = std::min({p_f, (min_r - max_r) / (x_hi - x_lo), (min_u - max_u) / (y_hi - y_lo)});
    double from_r = -INFINITY, to_r = INFINITY, from_u = -INFINITY, to_u = INFINITY;
    each_corner([&](const Vec3& i) {
      from_r = std::max(from_r, i.x() - x_hi * (i.z() - p_f));
      to_r = std::min(to_r, i.x() - x_lo * (i.z() - p_f));
      from_u = std::max(from_u, i.y() - y_hi * (i.z() - p_f));
      to_u = std::min(to_u, i.y() - y_lo * (i.z() - p_f));
    });
    p_r = 0.5 * (from_r + to_r);
    p_u = 0.5 * (from_u + to_u);
  } else {
    // The view passes through the given look_at: only the distance is free.
    each_corner([&](const Vec3& corner) {
      const double x = corner.x(), y = corner.y();
      p_f = std::min({p_f, corner.z() - clearance, corner.z() - (x > 0.0 ? x / x_hi : x / x_lo),
                      corner.z() - (y > 0.0 ? y / y_hi : y / y_lo)});
    });
  }
  camera.position = target + p_r * right + p_u * up + p_f * forward;
  camera.look_at = camera.position - p_f * forward;  // on the axis, level with the target
  return camera;
}

}  // namespace hsb
