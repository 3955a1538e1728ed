// The exact intersector: exact where the answer is known, and the reference
// the sphere tracer is held to on many random rays.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "field/glyph_pipeline.h"
#include "renderer/render/ray_scene.h"
#include "renderer/surface/ray_polynomial.h"
#include "tests/renderer/blob_pair.h"
#include "tests/renderer/sampled_crossing.h"

namespace hsb {
namespace {

Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

TraceSettings settings_for(Intersector method, double scene_size) {
  TraceSettings t;
  t.intersector = method;
  t.min_step = 1e-6 * scene_size;
  return t;
}

// All spans along one whole ray, through the real span BVH.
void collect_whole_ray(const BlobGeometry& blobs, const Vec3& o, const Vec3& d, FieldRay& ray) {
  const RayInterval whole{o, d, 0.0, 1e30};
  blobs.collect_spans(&whole, 1, &ray);
}

struct Crossings {
  double exact, sphere;
};

// Both methods on the same spans, collected through the real span BVH.
Crossings both(const BlobGeometry& blobs, const BlobField& field, const Vec3& o, const Vec3& d,
               double scene_size) {
  FieldRay ray;
  TraceStats stats;
  collect_whole_ray(blobs, o, d, ray);
  const std::vector<RaySpan> spans = ray.spans;
  const double exact = ray.first_crossing(field, o, d, 0.0, 1e30, settings_for(Intersector::exact, scene_size), stats);
  ray.spans = spans;
  const double sphere = ray.first_crossing(field, o, d, 0.0, 1e30, settings_for(Intersector::sphere, scene_size), stats);
  return {exact, sphere};
}

// Random rays from a sphere around `bounds` aimed at points inside it.
template <class F>
void random_rays(const Box3& bounds, int count, unsigned seed, F&& f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> n;
  const double radius = 1.5 * bounds.diagonal();
  for (int i = 0; i < count; ++i) {
    const Vec3 o = bounds.centre() + radius * Vec3(n(rng), n(rng), n(rng)).normalized();
    const Vec3 target = bounds.lo + bounds.size().cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
    // Single precision, as Embree sees them.
    f(o.cast<float>().cast<double>(), (target - o).normalized().cast<float>().cast<double>());
  }
}

// The criterion, over one scene: wherever the exact method finds a
// crossing, the sphere tracer finds the same one to 1e-5 of the scene size;
// a sphere-traced hit the exact method does not confirm must at least lie
// on the surface (a touch without a sign change).
void expect_sphere_matches_exact(const BlobField& field, int rays, unsigned seed, int* hits_out = nullptr) {
  const EmbreeDevice device;
  const Box3 bounds = influence_bounds(field);
  const double scene_size = bounds.diagonal();
  const BlobGeometry blobs(device.get(), field, settings_for(Intersector::sphere, scene_size));
  int hits = 0, touches = 0, missed = 0;
  random_rays(bounds, rays, seed, [&](const Vec3& o, const Vec3& d) {
    const Crossings c = both(blobs, field, o, d, scene_size);
    if (c.exact >= 0.0) {
      ++hits;
      if (c.sphere < 0.0) {
        ++missed;
        ADD_FAILURE() << "sphere tracer missed a crossing at t = " << c.exact << ", ray " << o.transpose()
                      << " → " << d.transpose();
        return;
      }
      EXPECT_NEAR(c.sphere, c.exact, 1e-5 * scene_size);
      // And the exact root is on the surface.
      EXPECT_NEAR(field_value(field, o + c.exact * d), field.isovalue, 1e-7);
    } else if (c.sphere >= 0.0) {
      ++touches;
      EXPECT_NEAR(field_value(field, o + c.sphere * d), field.isovalue, 1e-6);
    }
  });
  EXPECT_EQ(missed, 0);
  EXPECT_LT(touches, rays / 1000 + 1);
  if (hits_out) *hits_out = hits;
}

TEST(ExactCrossing, IsolatedGlyphIsTheExactEllipsoid) {
  for (KernelKind kernel : {KernelKind::wyvill, KernelKind::quartic}) {
    SCOPED_TRACE(kernel_name(kernel));
    std::mt19937 rng(5);
    const Mat3 axes = random_rotation(rng);
    const Vec3 centre(0.1, -0.2, 0.3), radii(0.8, 0.3, 0.05);
    BlobField field;
    field.kernel = kernel;
    field.sources.push_back(make_blob_source(centre, axes, radii, 1.0, {1, 1, 1}));
    // The analytic entry into the ellipsoid the source stores: |W(x − c)| = level,
    // with W and c as kept in single precision.
    const BlobSource& stored = field.sources[0];
    Mat3 w;
    for (int i = 0; i < 9; ++i) w(i / 3, i % 3) = stored.w[std::size_t(i)];
    const Vec3 c0(stored.centre[0], stored.centre[1], stored.centre[2]);
    const double level = kernel_level_radius(kernel, 0.5);
    const EmbreeDevice device;
    const BlobGeometry blobs(device.get(), field, settings_for(Intersector::exact, 1.0));
    int hits = 0;
    random_rays(influence_bounds(field), 20000, 9, [&](const Vec3& o, const Vec3& d) {
      const Vec3 p = w * (o - c0) / level, q = w * d / level;
      const double a = q.squaredNorm(), b = p.dot(q), c = p.squaredNorm() - 1, disc = b * b - a * c;
      FieldRay ray;
      TraceStats stats;
      collect_whole_ray(blobs, o, d, ray);
      const double t = ray.first_crossing(field, o, d, 0.0, 1e30, settings_for(Intersector::exact, 1.0), stats);
      if (disc <= 1e-12 * a) return;  // tangent within round-off: either answer
      ++hits;
      ASSERT_GE(t, 0.0);
      EXPECT_NEAR(t, (-b - std::sqrt(disc)) / a, 1e-9);
    });
    EXPECT_GT(hits, 2000);
  }
}

TEST(ExactCrossing, TwoSourcesBlendExactly) {
  const BlobField pair = blob_pair();
  const EmbreeDevice device;
  const BlobGeometry blobs(device.get(), pair, settings_for(Intersector::exact, 1.0));
  FieldRay ray;
  TraceStats stats;
  const Vec3 o(0, -5, 0), d(0, 1, 0);
  collect_whole_ray(blobs, o, d, ray);
  const double t = ray.first_crossing(pair, o, d, 0.0, 1e30, settings_for(Intersector::exact, 1.0), stats);
  EXPECT_NEAR(t, 5.0 - blob_pair_crossing_y(), 1e-12);
}

TEST(SphereAgainstExact, IsolatedGlyph) {
  std::mt19937 rng(21);
  BlobField field;
  field.sources.push_back(make_blob_source(Vec3(0, 0, 0), random_rotation(rng), Vec3(0.6, 0.25, 0.1), 1.0, {1, 1, 1}));
  int hits = 0;
  expect_sphere_matches_exact(field, 40000, 1, &hits);
  EXPECT_GT(hits, 4000);
}

TEST(SphereAgainstExact, DenseBlendedHyperstreamsurface) {
  // The point load's 7×7 hyperstreamsurface (paper Fig. 9), quartic kernel.
  GlyphPipelineSpec spec;
  SeedGridSpec grid;
  grid.corner = Vec3(-0.45, -0.45, 0.7);
  grid.edge_u = Vec3(0.9, 0, 0);
  grid.edge_v = Vec3(0, 0.9, 0);
  grid.n = grid.m = 7;
  spec.seeds.grids.push_back(grid);
  spec.trajectory.families = {EigenFamily::minor};
  spec.spacing = 0.02;
  spec.size.mapping = RadiusMapping::normalized;
  spec.size.scale = 0.13;
  spec.size.floor = 0.05;
  const GlyphScene glyphs = build_glyph_scene(spec, 0.5);
  ASSERT_GT(glyphs.sources.size(), 3000u);
  BlobField field = make_blob_field(glyphs.sources, std::vector<std::array<float, 3>>(glyphs.sources.size(), {1, 1, 1}),
                                    1.0, KernelKind::quartic, Blend::sum, 0.5);
  int hits = 0;
  expect_sphere_matches_exact(field, 40000, 2, &hits);
  EXPECT_GT(hits, 4000);
}

TEST(SphereAgainstExact, ThinNeedlesAndDiscs) {
  std::mt19937 rng(33);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  BlobField field;
  for (int i = 0; i < 60; ++i) {
    const Vec3 radii = i % 2 ? Vec3(0.4, 0.004, 0.004) : Vec3(0.3, 0.3, 0.003);  // needle : disc, 100:1
    field.sources.push_back(make_blob_source(Vec3(u(rng), u(rng), u(rng)), random_rotation(rng), radii, 1.0, {1, 1, 1}));
  }
  int hits = 0;
  expect_sphere_matches_exact(field, 40000, 3, &hits);
  EXPECT_GT(hits, 2000);
}

// A crowd: a few hundred large glyphs all overlapping, and an isovalue so
// high that no single one reaches it, so the surface lies deep in the
// crowd where every ray crosses hundreds of supports and the running bound
// does most of the work.
BlobField crowd(int n, double isovalue, KernelKind kernel) {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  BlobField field;
  field.kernel = kernel;
  for (int i = 0; i < n; ++i) {
    const Vec3 centre = 0.3 * Vec3(normal(rng), normal(rng), normal(rng));
    const Vec3 radii(1.5, 0.8 + 0.6 * unit(rng), 0.5 + 0.5 * unit(rng));
    field.sources.push_back(make_blob_source(centre, random_rotation(rng), radii, 1.0, {1, 1, 1}));
  }
  field.isovalue = isovalue;
  return field;
}

// The first crossing by brute force: F summed straight from the spans at
// 4,000 points along the ray, then bisection.
double brute_force_crossing(const BlobField& field, const std::vector<RaySpan>& spans, double t_end) {
  const auto f = [&](double t) {
    double sum = 0.0;
    for (const RaySpan& s : spans)
      if (s.t0 <= t && t <= s.t1) sum += kernel_value(field.kernel, s.g(t));
    return sum;
  };
  return sampled_crossing(f, field.isovalue, t_end, 4000);
}

TEST(ExactCrossing, CrowdOfOverlappingSourcesMatchesBruteForce) {
  for (KernelKind kernel : {KernelKind::wyvill, KernelKind::quartic}) {
    SCOPED_TRACE(kernel_name(kernel));
    const BlobField field = crowd(300, 20.0, kernel);
    const EmbreeDevice device;
    const BlobGeometry blobs(device.get(), field, settings_for(Intersector::exact, 4.0));
    int hits = 0, rays = 0, crossed = 0;
    // Aimed at the crowd's core, from all around it.
    const Box3 core{Vec3::Constant(-0.4), Vec3::Constant(0.4)};
    random_rays(core, 300, 17, [&](const Vec3& o, const Vec3& d) {
      ++rays;
      FieldRay ray;
      TraceStats stats;
      const double t_end = 2.0 * (o.norm() + influence_bounds(field).diagonal());
      collect_whole_ray(blobs, o, d, ray);
      const std::vector<RaySpan> spans = ray.spans;
      crossed += int(spans.size());
      const double t = ray.first_crossing(field, o, d, 0.0, 1e30, settings_for(Intersector::exact, 4.0), stats);
      const double expected = brute_force_crossing(field, spans, t_end);
      // A crossing the samples can straddle unseen is thinner than
      // t_end / 4,000; the grazing rays where that happens are few.
      if ((t < 0.0) != (expected < 0.0)) {
        EXPECT_NEAR(field_value(field, o + (t < 0 ? expected : t) * d), field.isovalue, 1e-3);
        return;
      }
      if (t < 0.0) return;
      ++hits;
      EXPECT_NEAR(t, expected, 1e-7 * t_end);
      // A shadow ray's question, on the same spans: any crossing at all.
      ray.spans = spans;
      const double any = ray.first_crossing(field, o, d, 0.0, 1e30, settings_for(Intersector::exact, 4.0), stats,
                                            CrossingQuery::any);
      ASSERT_GE(any, 0.0);
      EXPECT_GE(field_value(field, o + any * d), field.isovalue * (1.0 - 1e-9));
    });
    EXPECT_GT(hits, rays / 2);
    EXPECT_GT(double(crossed) / rays, 150.0);  // the supports a ray crosses: most of the crowd
  }
}

TEST(SphereAgainstExact, CrowdOfOverlappingSources) {
  expect_sphere_matches_exact(crowd(150, 30.0, KernelKind::wyvill), 4000, 19);
}


// The root finder evaluates a piece in powers of u: the conversion back
// from Bernstein form must give the polynomial that was converted, for
// every degree the kernels make.
TEST(RayPolynomial, BernsteinFormConvertsBack) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coefficient(-2.0, 2.0);
  for (int n = 1; n <= kMaxRayDegree; ++n) {
    RayPolynomial p{};
    for (int i = 0; i <= n; ++i) p[std::size_t(i)] = coefficient(rng);
    const RayPolynomial back = from_bernstein(to_bernstein(p, n), n);
    for (int i = 0; i <= n; ++i) EXPECT_NEAR(back[std::size_t(i)], p[std::size_t(i)], 1e-13) << "degree " << n;
    for (int i = n + 1; i <= kMaxRayDegree; ++i) EXPECT_EQ(back[std::size_t(i)], 0.0);
    // Horner's value and slope against the sums of powers.
    for (const double u : {0.0, 0.3, 1.0}) {
      double sum = 0.0, derivative = 0.0;
      for (int i = 0; i <= n; ++i) sum += p[std::size_t(i)] * std::pow(u, i);
      for (int i = 1; i <= n; ++i) derivative += double(i) * p[std::size_t(i)] * std::pow(u, i - 1);
      double slope;
      EXPECT_NEAR(power_value(p, n, u, slope), sum, 1e-14);
      EXPECT_NEAR(slope, derivative, 1e-13);
    }
  }
}

}  // namespace
}  // namespace hsb
