// Automatic cameras: whatever the view, projection, aspect and legend,
// everything framed is in the picture, inside the margin, and in front of
// the camera.

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/render/camera_framing.h"

namespace hsb {
namespace {

struct Projected {
  double x, y;    // in pixels
  double depth;   // along the view
};

Projected project(const CameraSpec& c, int width, int height, const Vec3& p) {
  const Vec3 forward = (c.look_at - c.position).normalized();
  const Vec3 right = forward.cross(c.up).normalized();
  const Vec3 down = forward.cross(right);
  const Vec3 q = p - c.position;
  const double depth = q.dot(forward);
  const double half_h = c.projection == Projection::perspective ? std::tan(0.5 * c.fov_degrees * M_PI / 180.0)
                                                                : 0.5 * c.height;
  const double half_w = half_h * width / height;
  const double scale = c.projection == Projection::perspective ? depth : 1.0;
  return {(q.dot(right) / scale / half_w + 1.0) * 0.5 * width, (q.dot(down) / scale / half_h + 1.0) * 0.5 * height,
          depth};
}

void expect_framed(const CameraSpec& camera, const Box3& box, int width, int height, double reserved, double margin) {
  double x_lo = 1e300, x_hi = -1e300, y_lo = 1e300, y_hi = -1e300;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner(i & 1 ? box.hi.x() : box.lo.x(), i & 2 ? box.hi.y() : box.lo.y(), i & 4 ? box.hi.z() : box.lo.z());
    const Projected p = project(camera, width, height, corner);
    EXPECT_GT(p.depth, 0.0) << "a corner behind the camera";
    x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x), y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
  }
  // The margin is a fraction of the free part's width and of the height.
  const double free_width = (1.0 - reserved) * width;
  const double slack = 0.01 * std::max(free_width, double(height));
  EXPECT_GE(x_lo, margin * free_width - slack);
  EXPECT_LE(x_hi, free_width - margin * free_width + slack);
  EXPECT_GE(y_lo, margin * height - slack);
  EXPECT_LE(y_hi, height - margin * height + slack);
  // And it is not a speck: it fills the free part in one direction.
  EXPECT_TRUE(x_hi - x_lo > 0.75 * free_width || y_hi - y_lo > 0.75 * height)
      << "x " << x_lo << "…" << x_hi << ", y " << y_lo << "…" << y_hi;
  // Centred in the free part.
  EXPECT_NEAR(0.5 * (x_lo + x_hi), 0.5 * free_width, 0.06 * free_width);
  EXPECT_NEAR(0.5 * (y_lo + y_hi), 0.5 * height, 0.06 * height);
  // Outside the box.
  EXPECT_FALSE(box.contains(camera.position));
}

TEST(CameraFraming, FitsTheBoxFromEveryViewAtAnyScale) {
  const Box3 boxes[] = {{Vec3(-1, -1, -1), Vec3(1, 1, 1)},
                        {Vec3(0, -0.02, -0.02), Vec3(0.1, 0.02, 0.02)},   // a bar in metres
                        {Vec3(-50, -20, 0), Vec3(50, 20, 5)},             // a plate in millimetres
                        {Vec3(3e5, 1e5, -2e3), Vec3(3.1e5, 1.4e5, 1e3)}}; // far from the origin
  for (const Box3& box : boxes) {
    for (const char* name : {"iso", "front", "back", "left", "right", "top", "bottom"}) {
      for (const Projection projection : {Projection::perspective, Projection::orthographic}) {
        for (const auto& [width, height, reserved] : {std::tuple{800, 800, 0.0}, std::tuple{1000, 400, 0.14},
                                                      std::tuple{300, 900, 0.3}}) {
          SCOPED_TRACE(std::string(name) + " " + std::to_string(width) + "x" + std::to_string(height));
          CameraRequest request;
          request.view = named_view(name);
          request.projection = projection;
          const CameraSpec camera = frame_camera(request, box, width, height, reserved);
          expect_framed(camera, box, width, height, reserved, request.margin);
        }
      }
    }
  }
}

TEST(CameraFraming, GivenPositionAndLookAtWin) {
  CameraRequest request;
  request.position = Vec3(5, 6, 7);
  request.look_at = Vec3(1, 2, 3);
  request.fov_degrees = 20;
  const CameraSpec c = frame_camera(request, Box3{Vec3::Zero(), Vec3::Ones()}, 100, 100);
  EXPECT_EQ(c.position, Vec3(5, 6, 7));
  EXPECT_EQ(c.look_at, Vec3(1, 2, 3));
  EXPECT_EQ(c.fov_degrees, 20);
  // Only a look_at: the camera comes from the view's side, as far as needed.
  CameraRequest aimed;
  aimed.look_at = Vec3(0.5, 0.5, 0.5);
  aimed.view = named_view("front");
  const CameraSpec a = frame_camera(aimed, Box3{Vec3::Zero(), Vec3::Ones()}, 100, 100);
  EXPECT_EQ(a.look_at, Vec3(0.5, 0.5, 0.5));
  EXPECT_NEAR((a.position - a.look_at).normalized().y(), -1.0, 1e-12);
}

TEST(CameraFraming, UpIsVerticalUnlessLookingAlongIt) {
  EXPECT_EQ(automatic_up(Vec3(1, -1, 1)), Vec3::UnitZ());
  EXPECT_EQ(automatic_up(Vec3(0, 0, 1)), Vec3::UnitY());
  EXPECT_EQ(automatic_up(Vec3(0, 0, -1)), Vec3::UnitY());
}

TEST(CameraFraming, LongBodiesAreSeenFromTheSide) {
  const Vec3 bar = automatic_view(Box3{Vec3::Zero(), Vec3(1, 0.1, 0.1)});
  EXPECT_LT(std::fabs(bar.x()), 0.35);  // mostly across the long x axis
  const Vec3 cube = automatic_view(Box3{Vec3::Zero(), Vec3(1, 1, 1)});
  EXPECT_GT(cube.x(), 0.3);
  EXPECT_LT(cube.y(), -0.3);
  EXPECT_GT(cube.z(), 0.2);
}

TEST(CameraFraming, AnEmptyBoxStillGivesACamera) {
  const Box3 point{Vec3(2, 2, 2), Vec3(2, 2, 2)};
  const CameraSpec c = frame_camera(CameraRequest{}, point, 64, 64);
  EXPECT_GT((c.position - c.look_at).norm(), 0.0);
  EXPECT_TRUE(c.position.allFinite());
}

}  // namespace
}  // namespace hsb
