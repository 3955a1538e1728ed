// The sphere-traced surface against exact answers, through the real Embree
// path (span BVH, user geometry callbacks).

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "renderer/render/ray_scene.h"
#include "renderer/surface/embree_ray.h"
#include "renderer/surface/ray_packets.h"
#include "tests/renderer/blob_pair.h"
#include "tests/renderer/camera_ray.h"

namespace hsb {
namespace {

struct AnalyticHit {
  bool hit = false;
  double t = 0.0;
  double chord = 0.0;  // length of the ray inside the ellipsoid
};

// Ray against the ellipsoid with centre c, axes (columns) and semi-axes s.
AnalyticHit ray_ellipsoid(const Vec3& o, const Vec3& d, const Vec3& c, const Mat3& axes, const Vec3& s) {
  const Vec3 p = (axes.transpose() * (o - c)).cwiseQuotient(s);
  const Vec3 q = (axes.transpose() * d).cwiseQuotient(s);
  const double a = q.squaredNorm(), b = 2 * p.dot(q), cc = p.squaredNorm() - 1;
  const double disc = b * b - 4 * a * cc;
  if (disc < 0) return {};
  const double t0 = (-b - std::sqrt(disc)) / (2 * a), t1 = (-b + std::sqrt(disc)) / (2 * a);
  if (t1 < 0) return {};
  return {true, std::max(t0, 0.0), (t1 - std::max(t0, 0.0)) * d.norm()};
}

Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  const Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

// Traces one ray through the scene; returns the field hit distance or −1.
double trace(const RayScene& scene, const Vec3& o, const Vec3& d) {
  const CameraHit hit = trace_camera_ray(scene, o, d);
  return hit.geom_id == scene.field_id() ? hit.t : -1.0;
}

TraceSettings sphere_settings(double min_step) {
  TraceSettings t;
  t.min_step = min_step;
  return t;
}

class IsolatedGlyph : public ::testing::TestWithParam<KernelKind> {};

TEST_P(IsolatedGlyph, SphereTracedHitIsTheExactEllipsoid) {
  const KernelKind kernel = GetParam();
  const EmbreeDevice device;
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double scene_size = 2.0;
  int rays = 0, hits = 0, grazing = 0;

  for (int glyph = 0; glyph < 20; ++glyph) {
    // Random pose and radii from round to strongly anisotropic (1:30).
    const Vec3 centre(0.3 * unit(rng), 0.3 * unit(rng), 0.3 * unit(rng));
    const Mat3 axes = random_rotation(rng);
    const Vec3 radii(0.5, 0.5 * std::pow(10.0, -0.75 * (unit(rng) + 1)),
                     0.5 * std::pow(10.0, -0.75 * (unit(rng) + 1)));
    const double R = 1.3, C = 0.5;
    BlobField field;
    field.kernel = kernel;
    field.isovalue = C;
    field.sources.push_back(make_blob_source(centre, axes, radii, R, {1, 1, 1}));
    const RayScene scene(device, field, sphere_settings(1e-6 * scene_size));
    const Vec3 semi_axes = R * kernel_level_radius(kernel, C) * radii;

    for (int i = 0; i < 500; ++i, ++rays) {
      const Vec3 o = 3.0 * Vec3(unit(rng), unit(rng), unit(rng)).normalized();
      // Aim inside the glyph's own box, a little beyond it: hits and misses.
      const Vec3 target = centre + axes * (1.2 * semi_axes).cwiseProduct(Vec3(unit(rng), unit(rng), unit(rng)));
      const Vec3 d = (target - o).normalized();
      // Both sides see the float ray Embree sees.
      const Vec3 of = o.cast<float>().cast<double>(), df = d.cast<float>().cast<double>();
      const AnalyticHit exact = ray_ellipsoid(of, df, centre.cast<float>().cast<double>(), axes, semi_axes);
      const double t = trace(scene, of, df);
      if (exact.hit && exact.chord < 1e-5 * scene_size) {
        ++grazing;  // a sliver thinner than the tracer's resolution: either answer is fine
        continue;
      }
      ASSERT_EQ(t >= 0.0, exact.hit) << "glyph " << glyph << " ray " << i;
      if (exact.hit) {
        ++hits;
        EXPECT_NEAR(t, exact.t, 1e-5 * scene_size) << "glyph " << glyph << " ray " << i;
      }
    }
  }
  EXPECT_GT(hits, rays / 5);  // the rays really test the surface
  EXPECT_LT(grazing, rays / 1000);
}

INSTANTIATE_TEST_SUITE_P(AllKernels, IsolatedGlyph,
                         ::testing::Values(KernelKind::wyvill, KernelKind::quartic, KernelKind::blinn),
                         [](const ::testing::TestParamInfo<KernelKind>& param) { return std::string(kernel_name(param.param)); });

TEST(Blending, TwoNearbySourcesBlendWhereEachAloneWouldMiss) {
  const EmbreeDevice device;
  BlobField pair = blob_pair();
  const Vec3 o(0, -5, 0), d(0, 1, 0);

  for (int i = 0; i < 2; ++i) {
    BlobField alone;
    alone.sources.push_back(pair.sources[std::size_t(i)]);
    const RayScene scene(device, alone, TraceSettings{});
    EXPECT_LT(trace(scene, o, d), 0.0) << "source " << i << " alone";
  }
  const RayScene blended(device, pair, TraceSettings{});
  const double t = trace(blended, o, d);
  ASSERT_GT(t, 0.0);
  EXPECT_NEAR(t, 5.0 - blob_pair_crossing_y(), 1e-9);

  // The same pair under blend = "max" is the plain union: the ray misses.
  pair.blend = Blend::max;
  const RayScene unioned(device, pair, TraceSettings{});
  EXPECT_LT(trace(unioned, o, d), 0.0);
}

// The pair's first crossing along o + t d, by `tracer` given both its
// spans (whose last spans then shade it).
double crossing_with_both_spans(const BlobField& pair, FieldRay& tracer, const Vec3& o, const Vec3& d,
                                const TraceSettings& settings) {
  for (std::uint32_t i = 0; i < 2; ++i) {
    RaySpan span;
    if (!ray_span(pair.sources[i], i, 0, o, d, 0.0, 100.0, span)) {
      ADD_FAILURE() << "the ray misses source " << i;
      return -1.0;
    }
    tracer.spans.push_back(span);
  }
  TraceStats stats;
  return tracer.first_crossing(pair, o, d, 0.0, 100.0, settings, stats);
}

// Sources of two groups (two line families) are two surfaces: the pair's
// blend between them is gone, each source still stands as it does alone,
// and what a ray hits is shaded by its own group alone. For both
// intersectors and for a shape other than the ellipsoid.
TEST(Blending, GroupsAreSurfacesOfTheirOwn) {
  const EmbreeDevice device;
  for (const GlyphShape shape : {GlyphShape::ellipsoid, GlyphShape::superquadric}) {
    for (const Intersector intersector : {Intersector::exact, Intersector::sphere}) {
      BlobField pair = blob_pair();
      pair.shape = shape;
      if (shape != GlyphShape::ellipsoid) pair.shapes.assign(2, ShapeParams{});  // round: the ellipsoid's exponents
      pair.groups = {0, 2};
      TraceSettings settings;
      settings.intersector = intersector;
      const RayScene grouped(device, pair, settings);
      const std::string what = std::string(glyph_shape_name(shape)) + (intersector == Intersector::exact ? ", exact" : ", sphere");
      EXPECT_LT(trace(grouped, Vec3(0, -5, 0), Vec3(0, 1, 0)), 0.0) << what;  // through the blend: nothing
      // Along x, from the blue side: the blue source's own sphere of
      // radius ½ about x = 0.55, entered at x = 1.05; the red one's
      // influence does not reach the blue surface.
      EXPECT_NEAR(trace(grouped, Vec3(5, 0, 0), Vec3(-1, 0, 0)), 5.0 - (double(0.55f) + 0.5), 1e-9) << what;
      // A ray near the red source, inside the blue one's support: its
      // colour is pure red.
      const Vec3 o(-0.3, -5, 0), d(0, 1, 0);
      FieldRay tracer;
      const double t = crossing_with_both_spans(pair, tracer, o, d, settings);
      ASSERT_GT(t, 0.0) << what;
      const SurfaceSample sample = tracer.surface_at(pair, o, d, t);
      EXPECT_FLOAT_EQ(sample.color[0], 1.0f) << what;
      EXPECT_FLOAT_EQ(sample.color[2], 0.0f) << what;
      // F of the union is the larger group's: C on the red surface.
      EXPECT_NEAR(field_value(pair, o + t * d), 0.5, 1e-9) << what;
    }
  }
}

TEST(Blending, ColourIsTheInfluenceWeightedMixAndNormalIsTheGradient) {
  const BlobField pair = blob_pair();
  const Vec3 o(-0.1, -5, 0), d(0, 1, 0);
  FieldRay tracer;
  const double t = crossing_with_both_spans(pair, tracer, o, d, TraceSettings{});
  ASSERT_GT(t, 0.0);
  const Vec3 x = o + t * d;
  EXPECT_NEAR(field_value(pair, x), 0.5, 1e-9);
  const SurfaceSample s = tracer.surface_at(pair, o, d, t);
  // Nearer the left (red) source, so more red than blue, and only those two.
  EXPECT_GT(s.color[0], s.color[2]);
  EXPECT_NEAR(s.color[0] + s.color[2], 1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(s.color[1], 0.0f);
  // Normal = −∇F/|∇F| by central differences.
  const double h = 1e-6;
  Vec3 grad;
  for (int k = 0; k < 3; ++k) {
    Vec3 e = Vec3::Zero();
    e[k] = h;
    grad[k] = (field_value(pair, x + e) - field_value(pair, x - e)) / (2 * h);
  }
  EXPECT_LT((s.normal + grad.normalized()).norm(), 1e-6);
  EXPECT_LT(s.normal.dot(d), 0.0);  // faces the viewer
}

// Camera and shadow rays are traced in packets; each ray must get the
// answer it gets alone, whichever lanes are active, at every packet width:
// the device's own, and wider ones that Embree splits (and may reorder)
// before calling the field geometry back with fewer lanes than were asked.
// The suite runs this under every instruction set the processor has
// (HSB_ISA, tests/CMakeLists.txt), so every width Embree calls back with
// is met on any machine.
TEST(Packets, EachRayAnswersAsItsRayAlone) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  BlobField field;
  for (int i = 0; i < 400; ++i) {
    const Vec3 radii(0.15, 0.15 * std::pow(10.0, -0.5 * (unit(rng) + 1)), 0.04);
    field.sources.push_back(make_blob_source(Vec3(unit(rng), unit(rng), unit(rng)), random_rotation(rng),
                                             radii, 1.3, {1, 1, 1}));
  }
  const EmbreeDevice device;
  for (Intersector method : {Intersector::sphere, Intersector::exact}) {
    TraceSettings settings;
    settings.intersector = method;
    const RayScene scene(device, field, settings);
    for (int width : {1, 4, 8, 16}) {
      int hits = 0, occluded = 0;
      for (int packet = 0; packet < 120; ++packet) {
        // Alternate coherent packets (a small cone from one point) and
        // scattered ones, with coherent and incoherent contexts; leave
        // some rays out.
        const bool coherent = packet % 2 == 0;
        const Vec3 eye = 4.0 * Vec3(unit(rng), unit(rng), unit(rng)).normalized();
        const Vec3 aim = 0.5 * Vec3(unit(rng), unit(rng), unit(rng));
        Vec3 origin[kMaxPacket], direction[kMaxPacket];
        unsigned traced = 0;  // with holes: finished rays leave them
        for (int i = 0; i < kMaxPacket; ++i) {
          if (unit(rng) > -0.7) traced |= 1u << i;
          const Vec3 from = coherent ? eye : 4.0 * Vec3(unit(rng), unit(rng), unit(rng)).normalized();
          const Vec3 scatter(unit(rng), unit(rng), unit(rng));
          const Vec3 target = coherent ? Vec3(aim + 0.1 * scatter) : Vec3(0.8 * scatter);
          direction[i] = (target - from).normalized().cast<float>().cast<double>();
          origin[i] = from.cast<float>().cast<double>();
        }
        FieldRayLanes tracers;
        TraceStats stats;
        FieldRayContext context(tracers, stats);
        FieldRayContext shadow_context(tracers, stats);
        if (coherent) context.embree.flags = shadow_context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        unsigned geometry[kMaxPacket];
        float tfar[kMaxPacket], shadow_tfar[kMaxPacket];
        intersect_rays(
            scene.get(), &context.embree, width, traced,
            [&](RTCRayHitN* p, unsigned n, unsigned lane, int i) {
              set_embree_ray(p, n, lane, unsigned(i), origin[i], direction[i], 0.0f, INFINITY);
            },
            [&](RTCRayHitN* p, unsigned n, unsigned lane, int i) {
              geometry[i] = RTCHitN_geomID(RTCRayHitN_HitN(p, n), n, lane);
              tfar[i] = RTCRayN_tfar(RTCRayHitN_RayN(p, n), n, lane);
            });
        occluded_rays(
            scene.get(), &shadow_context.embree, width, traced,
            [&](RTCRayN* p, unsigned n, unsigned lane, int i) {
              set_embree_ray(p, n, lane, unsigned(i), origin[i], direction[i], 0.0f, INFINITY);
            },
            [&](RTCRayN* p, unsigned n, unsigned lane, int i) { shadow_tfar[i] = RTCRayN_tfar(p, n, lane); });

        for (int i = 0; i < kMaxPacket; ++i) {
          if (!(traced & (1u << i))) continue;
          const double alone = trace(scene, origin[i], direction[i]);
          const bool hit = geometry[i] == scene.field_id();
          ASSERT_EQ(hit, alone >= 0.0) << "width " << width << " packet " << packet << " ray " << i;
          ASSERT_EQ(shadow_tfar[i] < 0.0f, hit) << "width " << width << " packet " << packet << " ray " << i;
          if (!hit) continue;
          ++hits;
          EXPECT_NEAR(context.t[std::size_t(i)], alone, 1e-12) << "width " << width << " packet " << packet;
          EXPECT_EQ(tfar[i], float(alone));
          // The surface sample is the ray's own: its normal faces the ray.
          EXPECT_LT(context.surface[std::size_t(i)].normal.dot(direction[i]), 0.0)
              << "width " << width << " packet " << packet << " ray " << i;
          occluded += shadow_tfar[i] < 0.0f;
        }
      }
      EXPECT_GT(hits, 400) << "width " << width;
      EXPECT_EQ(occluded, hits) << "width " << width;
    }
  }
}

}  // namespace
}  // namespace hsb
