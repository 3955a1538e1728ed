// The top-level scene: what camera rays and shadow rays meet.

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/render/ray_scene.h"
#include "renderer/surface/embree_ray.h"
#include "tests/renderer/blob_pair.h"
#include "tests/renderer/camera_ray.h"

namespace hsb {
namespace {

struct Traced {
  unsigned camera_hit;  // geometry a camera ray meets first
  bool shadowed;        // whether a shadow ray on the same line is blocked
};

Traced trace_both(const RayScene& scene, const Vec3& o, const Vec3& d) {
  FieldRayLanes tracers;
  TraceStats stats;
  FieldRayContext shadow_context(tracers, stats);
  RTCRayHit shadow{};
  set_embree_ray(reinterpret_cast<RTCRayHitN*>(&shadow), 1, 0, 0, o, d, 0.0f, INFINITY, RayScene::kShadowRayMask);
  rtcOccluded1(scene.get(), &shadow_context.embree, &shadow.ray);
  return {trace_camera_ray(scene, o, d).geom_id, shadow.ray.tfar < 0.0f};
}

// The domain's edges are drawn but cast no shadow: a thin dark line across
// a glyph would read as a feature of the data.
TEST(RayScene, BoxEdgesAreSeenButCastNoShadow) {
  const EmbreeDevice device;
  const BlobField pair = blob_pair();  // near the origin, well inside the box
  const Box3 domain{Vec3(-2, -2, -2), Vec3(2, 2, 2)};
  DrawnContext context;
  context.box = domain;
  context.box_radius = domain.diagonal() / 500.0;
  const RayScene scene(device, pair, TraceSettings{}, context);
  ASSERT_NE(scene.box_id(), RTC_INVALID_GEOMETRY_ID);

  // Straight down onto the top front edge (y = −2, z = 2), from above it.
  const Traced edge = trace_both(scene, Vec3(0, -2, 3), Vec3(0, 0, -1));
  EXPECT_EQ(edge.camera_hit, scene.box_id());
  EXPECT_FALSE(edge.shadowed);

  // The field itself still casts shadows.
  const Traced field = trace_both(scene, Vec3(0, 0, 3), Vec3(0, 0, -1));
  EXPECT_EQ(field.camera_hit, scene.field_id());
  EXPECT_TRUE(field.shadowed);
}

}  // namespace
}  // namespace hsb
