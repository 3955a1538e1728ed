#include "renderer/render/camera_framing.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "base/point_extremes.h"

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
  std::vector<Vec3> stand_in;
  const bool nothing = !(box.diagonal() > 0.0) || !box.lo.allFinite() || !box.hi.allFinite();
  if (nothing) {
    const Vec3 c = box.centre().allFinite() ? box.centre() : Vec3::Zero();
    box = {c - Vec3::Constant(0.5), c + Vec3::Constant(0.5)};
    const std::array<Vec3, 8> corners = box.corners();
    stand_in.assign(corners.begin(), corners.end());
  }
  // The finite points, where they stand: a glyph field's are 14 a glyph
  // (11 MB for 33,768), which a copy would take again from the system.
  const std::vector<Vec3>& points = nothing ? stand_in : framed_points;
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
    const std::array<double, 4> least = least_values(points, [&](const Vec3& p) {
      const double x = (p - target).dot(right), y = (p - target).dot(up);
      return std::array<double, 4>{x, -x, y, -y};
    });
    const double x_lo = least[0], x_hi = -least[1], y_lo = least[2], y_hi = -least[3];
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
  const auto in_view = [&](const Vec3& p) {
    const Vec3 q = p - target;
    return Vec3(q.dot(right), q.dot(up), q.dot(forward));
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
    const std::array<double, 5> sides = least_values(points, [&](const Vec3& p) {
      const Vec3 c = in_view(p);
      return std::array<double, 5>{c.z() - clearance, c.x() - x_lo * c.z(), -(c.x() - x_hi * c.z()),
                                   c.y() - y_lo * c.z(), -(c.y() - y_hi * c.z())};
    });
    const double min_r = sides[1], max_r = -sides[2], min_u = sides[3], max_u = -sides[4];
    p_f = std::min({sides[0], (min_r - max_r) / (x_hi - x_lo), (min_u - max_u) / (y_hi - y_lo)});
    const std::array<double, 4> room = least_values(points, [&](const Vec3& p) {
      const Vec3 c = in_view(p);
      return std::array<double, 4>{-(c.x() - x_hi * (c.z() - p_f)), c.x() - x_lo * (c.z() - p_f),
                                   -(c.y() - y_hi * (c.z() - p_f)), c.y() - y_lo * (c.z() - p_f)};
    });
    const double from_r = -room[0], to_r = room[1], from_u = -room[2], to_u = room[3];
    p_r = 0.5 * (from_r + to_r);
    p_u = 0.5 * (from_u + to_u);
  } else {
    // The view passes through the given look_at: only the distance is free.
    p_f = least_values(points, [&](const Vec3& p) {
      const Vec3 c = in_view(p);
      const double x = c.x(), y = c.y();
      return std::array<double, 1>{std::min({c.z() - clearance, c.z() - (x > 0.0 ? x / x_hi : x / x_lo),
                                             c.z() - (y > 0.0 ? y / y_hi : y / y_lo)})};
    })[0];
  }
  camera.position = target + p_r * right + p_u * up + p_f * forward;
  camera.look_at = camera.position - p_f * forward;  // on the axis, level with the target
  return camera;
}

}  // namespace hsb
