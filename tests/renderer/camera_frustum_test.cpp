// A rectangle of the picture that is said to see nothing of a box must
// see nothing of it: no ray through it meets the box (a rectangle skipped
// wrongly would leave glyphs out of the picture). And a rectangle whose
// rays do meet the box, or a box around the eye, is never skipped.

#include <gtest/gtest.h>

#include <random>

#include "renderer/render/camera_frustum.h"

namespace hsb {
namespace {

// Whether the ray meets the box (slabs), ahead of its origin.
bool ray_meets(const CameraRay& ray, const Box3& box) {
  double t0 = 0.0, t1 = INFINITY;
  for (int a = 0; a < 3; ++a) {
    const double inverse = 1.0 / ray.direction[a];
    double near = (box.lo[a] - ray.origin[a]) * inverse, far = (box.hi[a] - ray.origin[a]) * inverse;
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
  }
  return t0 <= t1;
}

TEST(CameraFrustum, ARectangleSaidToSeeNothingSeesNothing) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0), centred(-1.0, 1.0);
  int skipped = 0, seen = 0;
  for (int trial = 0; trial < 400; ++trial) {
    CameraSpec spec;
    spec.position = Vec3(centred(random), centred(random), centred(random)) * 10.0;
    spec.look_at = Vec3(centred(random), centred(random), centred(random));
    if (trial % 2) {
      spec.projection = Projection::orthographic;
      spec.height = 1.0 + 6.0 * unit(random);
    }
    const int width = 64, height = 48;
    const Camera camera(spec, width, height);
    const Vec3 centre(centred(random) * 3.0, centred(random) * 3.0, centred(random) * 3.0);
    const Vec3 half(0.05 + unit(random), 0.05 + unit(random), 0.05 + unit(random));
    const Box3 box{centre - half, centre + half};
    for (int tile = 0; tile < 48; ++tile) {
      const int x0 = int(unit(random) * (width - 4)), y0 = int(unit(random) * (height - 4));
      const bool may_see = rectangle_may_see(camera, x0, y0, x0 + 4, y0 + 4, box);
      bool meets = false;
      for (int i = 0; i <= 16 && !meets; ++i)
        for (int j = 0; j <= 16 && !meets; ++j) meets = ray_meets(camera.ray(x0 + i / 4.0, y0 + j / 4.0), box);
      if (meets) {
        EXPECT_TRUE(may_see) << "trial " << trial << " tile at " << x0 << ", " << y0;
      }
      skipped += !may_see;
      seen += meets;
    }
  }
  // Both kinds occurred: the test says something either way.
  EXPECT_GT(skipped, 1000);
  EXPECT_GT(seen, 1000);
}

TEST(CameraFrustum, ABoxAroundTheEyeOrEmptyIsDecidedRightly) {
  CameraSpec spec;
  const Camera camera(spec, 40, 30);
  const Box3 around{spec.position - Vec3::Constant(0.5), spec.position + Vec3::Constant(0.5)};
  EXPECT_TRUE(rectangle_may_see(camera, 0, 0, 4, 4, around));
  // Behind the eye, on the line of sight: the rays go the other way.
  const Vec3 behind = spec.position + (spec.position - spec.look_at);
  EXPECT_FALSE(rectangle_may_see(camera, 18, 13, 22, 17, {behind - Vec3::Constant(0.1), behind + Vec3::Constant(0.1)}));
  EXPECT_TRUE(rectangle_may_see(camera, 18, 13, 22, 17, {spec.look_at - Vec3::Constant(0.1), spec.look_at + Vec3::Constant(0.1)}));
  const Box3 empty{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
  EXPECT_FALSE(rectangle_may_see(camera, 0, 0, 40, 30, empty));
}

}  // namespace
}  // namespace hsb
