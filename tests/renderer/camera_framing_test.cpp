// Automatic cameras: whatever the view, projection, aspect and legend,
// everything framed is in the picture, inside the margin, and in front of
// the camera.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "renderer/library/prepared_scene.h"
#include "renderer/render/camera.h"
#include "renderer/render/camera_framing.h"
#include "renderer/render/ray_scene.h"

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
  // The view describes the frame, the picture's top-left part.
  const double frame_w = c.frame_width * width, frame_h = c.frame_height * height;
  const double half_w = half_h * frame_w / frame_h;
  const double scale = c.projection == Projection::perspective ? depth : 1.0;
  return {(q.dot(right) / scale / half_w + 1.0) * 0.5 * frame_w, (q.dot(down) / scale / half_h + 1.0) * 0.5 * frame_h,
          depth};
}

void expect_framed(const CameraSpec& camera, const Box3& box, int width, int height, const PictureReserve& reserve,
                   double margin) {
  double x_lo = 1e300, x_hi = -1e300, y_lo = 1e300, y_hi = -1e300;
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner(i & 1 ? box.hi.x() : box.lo.x(), i & 2 ? box.hi.y() : box.lo.y(), i & 4 ? box.hi.z() : box.lo.z());
    const Projected p = project(camera, width, height, corner);
    EXPECT_GT(p.depth, 0.0) << "a corner behind the camera";
    x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x), y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
  }
  // The margin is a fraction of the free part's width and height.
  const double free_width = (1.0 - reserve.right) * width, free_height = (1.0 - reserve.bottom) * height;
  const double slack = 0.01 * std::max(free_width, free_height);
  EXPECT_GE(x_lo, margin * free_width - slack);
  EXPECT_LE(x_hi, free_width - margin * free_width + slack);
  EXPECT_GE(y_lo, margin * free_height - slack);
  EXPECT_LE(y_hi, free_height - margin * free_height + slack);
  // And it is not a speck: it fills the free part in one direction.
  EXPECT_TRUE(x_hi - x_lo > 0.75 * free_width || y_hi - y_lo > 0.75 * free_height)
      << "x " << x_lo << "…" << x_hi << ", y " << y_lo << "…" << y_hi;
  // Centred in the free part.
  EXPECT_NEAR(0.5 * (x_lo + x_hi), 0.5 * free_width, 0.06 * free_width);
  EXPECT_NEAR(0.5 * (y_lo + y_hi), 0.5 * free_height, 0.06 * free_height);
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
        for (const auto& [width, height, reserve] :
             {std::tuple{800, 800, PictureReserve{}}, std::tuple{1000, 400, PictureReserve{0.14, 0.0}},
              std::tuple{300, 900, PictureReserve{0.3, 0.0}}, std::tuple{600, 700, PictureReserve{0.0, 0.2}}}) {
          SCOPED_TRACE(std::string(name) + " " + std::to_string(width) + "x" + std::to_string(height));
          CameraRequest request;
          request.view = named_view(name);
          request.projection = projection;
          const CameraSpec camera = frame_camera(request, box, width, height, reserve);
          expect_framed(camera, box, width, height, reserve, request.margin);
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

TEST(CameraFraming, AFixedViewDescribesThePartLeftOfTheLegend) {
  CameraRequest request;
  request.position = Vec3(5, 6, 7);
  request.look_at = Vec3(1, 2, 3);
  const int width = 1000, height = 600;
  const CameraSpec spec = frame_camera(request, Box3{Vec3::Zero(), Vec3::Ones()}, width, height, {0.2, 0.0});
  const Camera camera(spec, width, height);
  // The ray through the middle of the free part (800 px wide) looks at look_at.
  const CameraRay middle = camera.ray(0.5 * 0.8 * width, 0.5 * height);
  EXPECT_NEAR(middle.direction.dot((request.look_at.value() - spec.position).normalized()), 1.0, 1e-12);
  // The field of view spans the picture's height, as without a legend.
  const CameraRay top = camera.ray(0.5 * 0.8 * width, 0.0);
  EXPECT_NEAR(std::acos(top.direction.dot(middle.direction)) * 180.0 / M_PI, 0.5 * spec.fov_degrees, 1e-9);
}

TEST(CameraFraming, UpIsVerticalUnlessLookingAlongIt) {
  EXPECT_EQ(automatic_up(Vec3(1, -1, 1)), Vec3::UnitZ());
  EXPECT_EQ(automatic_up(Vec3(0, 0, 1)), Vec3::UnitY());
  EXPECT_EQ(automatic_up(Vec3(0, 0, -1)), Vec3::UnitY());
  EXPECT_EQ(automatic_up(Vec3(0.1, -0.2, 1)), Vec3::UnitY());  // nearly along it
}

TEST(CameraFraming, LongBodiesAreSeenFromTheSide) {
  const Vec3 bar = automatic_view(Box3{Vec3::Zero(), Vec3(1, 0.1, 0.1)});
  EXPECT_LT(std::fabs(bar.x()), 0.35);  // mostly across the long x axis
  const Vec3 cube = automatic_view(Box3{Vec3::Zero(), Vec3(1, 1, 1)});
  EXPECT_GT(cube.x(), 0.3);
  EXPECT_LT(cube.y(), -0.3);
  EXPECT_GT(cube.z(), 0.2);
}

TEST(CameraFraming, FlatBodiesAreSeenFacingTheirFaces) {
  // A plate in the xy plane from above, one in xz from the front, one in
  // yz from the right: within 20° of square, never edge-on.
  const Vec3 normals[] = {Vec3::UnitZ(), -Vec3::UnitY(), Vec3::UnitX()};
  const Vec3 sizes[] = {Vec3(2, 1, 0.05), Vec3(1, 0.01, 3), Vec3(0.1, 1, 1)};
  for (int i = 0; i < 3; ++i) {
    const Vec3 view = automatic_view(Box3{Vec3::Zero(), sizes[i]});
    EXPECT_GT(view.dot(normals[i]), std::cos(20.0 * M_PI / 180.0)) << sizes[i].transpose();
    EXPECT_LT(view.dot(normals[i]), std::cos(10.0 * M_PI / 180.0)) << "square on, no relief: " << sizes[i].transpose();
  }
  // A beam as high as it is wide is not flat: seen from the side.
  const Vec3 beam = automatic_view(Box3{Vec3::Zero(), Vec3(2, 0.1, 0.2)});
  EXPECT_LT(std::fabs(beam.z()), 0.7);
}

TEST(CameraFraming, AnEmptyBoxStillGivesACamera) {
  const Box3 point{Vec3(2, 2, 2), Vec3(2, 2, 2)};
  const CameraSpec c = frame_camera(CameraRequest{}, point, 64, 64);
  EXPECT_GT((c.position - c.look_at).norm(), 0.0);
  EXPECT_TRUE(c.position.allFinite());
}

}  // namespace
}  // namespace hsb

namespace hsb {
namespace {

// Where the ray through image position (x, y) meets the plane facing the
// camera at `depth` along `forward` from `eye`.
Vec3 on_plane(const Camera& camera, const Vec3& eye, const Vec3& forward, double depth, double x, double y) {
  const CameraRay r = camera.ray(x, y);
  const Vec3 o = r.origin, d = r.direction;
  return o + ((depth - (o - eye).dot(forward)) / d.dot(forward)) * d;
}

// A pixel's size at a point is the spacing of neighbouring pixels' rays in
// the plane through the point, facing the camera.
TEST(Camera, PixelSizeIsTheSpacingOfNeighbouringRaysAtThatDepth) {
  for (const Projection projection : {Projection::perspective, Projection::orthographic}) {
    CameraSpec spec;
    spec.projection = projection;
    spec.position = Vec3(3, -5, 2);
    spec.look_at = Vec3(0.2, 0.1, -0.3);
    spec.fov_degrees = 35;
    spec.height = 2.5;
    spec.frame_width = 0.8;  // a legend's place on the right
    const Camera camera(spec, 300, 200);
    const Vec3 forward = (spec.look_at - spec.position).normalized();
    const Vec3 point = spec.position + 4.0 * forward + Vec3(0.3, -0.2, 0.1);
    const double depth = (point - spec.position).dot(forward);
    const Vec3 here = on_plane(camera, spec.position, forward, depth, 120, 100);
    const double across = (on_plane(camera, spec.position, forward, depth, 121, 100) - here).norm();
    const double down = (on_plane(camera, spec.position, forward, depth, 120, 101) - here).norm();
    EXPECT_NEAR(camera.pixel_size_at(point), across, 1e-9 * across);
    EXPECT_NEAR(camera.pixel_size_at(point), down, 1e-9 * down);
  }
}

// Glyphs the camera frames by themselves stay whole in the picture
// whatever their shape: a sharp superquadric reaches out to the rims and
// corners of its box, beyond the ellipsoid of the same radii. Every point
// of each isolated glyph's own surface (along 26 axis, edge and corner
// directions and 400 random ones) lies in the frame.
TEST(CameraFraming, EveryGlyphShapeStaysWholeInThePicture) {
  const std::string scene = "[[seeds.grid]]\ncorner = [-0.4, -0.4, 0.6]\nedge_u = [0.8, 0, 0]\nedge_v = [0, 0.8, 0]\n"
                            "n = 3\nm = 3\n[trajectories]\nfamily = \"minor\"\n[glyphs]\nspacing = 0.2\nmapping = \"normalized\"\nscale = 0.6\n"
                            "[render]\nwidth = 160\nheight = 120\nground = false\nbox = false\n";
  std::vector<Vec3> directions;
  for (int i = 0; i < 27; ++i)
    if (i != 13) directions.push_back(Vec3(i % 3 - 1, i / 3 % 3 - 1, i / 9 - 1).normalized());
  std::mt19937 rng(3);
  std::normal_distribution<double> n;
  for (int i = 0; i < 400; ++i) directions.push_back(Vec3(n(rng), n(rng), n(rng)).normalized());
  for (const std::vector<std::string>& shape :
       {std::vector<std::string>{}, {"glyphs.shape=\"superquadric\"", "glyphs.sharpness=10"},
        {"glyphs.shape=\"signed\"", "glyphs.sharpness=10", "output.colorbar=false"}}) {
    SCOPED_TRACE(shape.empty() ? "ellipsoid" : shape.front());
    const ColorManagement color("", "");
    const std::unique_ptr<PreparedScene> p = prepare_scene(load_scene_text(scene, "sharp.toml", "", shape), color);
    const BlobField& field = p->field;
    const double u_level = kernel_level_radius(field.kernel, field.isovalue);
    int outside = 0;
    for (std::size_t i = 0; i < field.sources.size(); ++i) {
      // x = c + W_s⁻¹ q_s: q_s = q/σ, the glyph's own frame scaled into the
      // stored one, and u(q) = √g(q_s) scales a direction onto the level.
      const ShapeParams& params = shape_params(field, i);
      const double sigma = params.bound_scale;
      const Mat3 inverse = shape_matrix(field.sources[i]).inverse();
      const Vec3 c(field.sources[i].centre[0], field.sources[i].centre[1], field.sources[i].centre[2]);
      for (const Vec3& w : directions) {
        const double u = std::sqrt(shape_g(field.shape, params, w / sigma));
        const Projected at = project(p->camera, p->render.width, p->render.height, c + inverse * (u_level / u * w / sigma));
        const double frame_w = p->camera.frame_width * p->render.width, frame_h = p->camera.frame_height * p->render.height;
        outside += at.depth <= 0.0 || at.x < 0.0 || at.x > frame_w || at.y < 0.0 || at.y > frame_h;
      }
    }
    EXPECT_EQ(outside, 0);
  }
}

}  // namespace
}  // namespace hsb
