// Superquadric and signed glyphs (renderer/surface/glyph_shape.h):
// Kindlmann's exponents as Teem computes them, the signed glyph's points,
// the bounds every shape promises the renderer (g_e ≤ g, the cube, |∇u| ≤
// Lσ in the stored frame, u convex along rays), and the tracer on blended
// and united glyphs against dense sampling along random rays: no crossing
// missed, none misplaced.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <random>

#include "renderer/render/ray_scene.h"
#include "renderer/surface/blob_geometry.h"
#include "renderer/surface/field_ray.h"
#include "renderer/surface/glyph_shape.h"
#include "tests/renderer/sampled_crossing.h"
#include "tests/renderer/span_sources.h"

namespace hsb {
namespace {

// Teem's `tend glyph -g sqd -sh 3` for diag(1, 0.5, 0.2) (src/ten/glyph.c):
// c_l = 0.294 < c_p = 0.353, so round about e3, α = (1 − c_l)³ = 0.352 and
// β = (1 − c_p)³ = 0.271; for diag(1, 0.2, 0.1) c_l > c_p: round about e1.
TEST(Superquadric, ExponentsAreKindlmannsAsTeemComputesThem) {
  const ShapeParams planar = superquadric_params(Vec3(1.0, 0.5, 0.2), 3.0);
  EXPECT_EQ(planar.axis, 2);
  EXPECT_NEAR(planar.alpha, std::pow(1.0 - 0.5 / 1.7, 3.0), 1e-6);
  EXPECT_NEAR(planar.beta, std::pow(1.0 - 0.6 / 1.7, 3.0), 1e-6);
  const ShapeParams linear = superquadric_params(Vec3(0.2, 1.0, 0.1), 3.0);  // longest radius second
  EXPECT_EQ(linear.axis, 1);
  EXPECT_NEAR(linear.alpha, std::pow(1.0 - 0.2 / 1.3, 3.0), 1e-6);
  EXPECT_NEAR(linear.beta, std::pow(1.0 - 0.8 / 1.3, 3.0), 1e-6);
  // No sharpness: the ellipsoid's exponents, and no bound to widen.
  const ShapeParams round = superquadric_params(Vec3(1.0, 0.5, 0.2), 0.0);
  EXPECT_FLOAT_EQ(round.alpha, 1.0f);
  EXPECT_FLOAT_EQ(round.beta, 1.0f);
  EXPECT_NEAR(round.bound_scale, 1.0, 1e-5);
  // Sharp and nearly a cube: σ near √3, never above.
  const ShapeParams cube = superquadric_params(Vec3(1.0, 1.0, 1.0), 10.0);
  EXPECT_GT(cube.bound_scale, 1.0);
  EXPECT_LE(cube.bound_scale, std::sqrt(3.0) * (1.0 + 1e-5));
}

// σ is the least bound, not only a bound: in the stored frame (q scaled
// by 1/σ, so that g_e = |q|² ≤ g) the bounding ellipsoid touches the glyph,
// |q|/u reaching 1 over a net of directions to within the net's spacing (a
// loose σ would widen every span and slow every superquadric ray), sharp
// glyphs whose exponents reach 10⁻⁹ among them. (That it is a bound:
// KeepTheBoundsTheTracerRestsOn.)
TEST(Superquadric, BoundScaleIsTheLargestRatioOfDistanceToGauge) {
  std::vector<ShapeParams> shapes;
  for (const Vec3& radii : {Vec3(1.0, 0.5, 0.2), Vec3(1.0, 0.05, 0.04), Vec3(1.0, 0.98, 0.01), Vec3(1.0, 1.0, 1.0),
                            Vec3(0.3, 1.0, 0.9)})
    for (double sharpness : {1.0, 3.0, 10.0}) shapes.push_back(superquadric_params(radii, sharpness));
  for (const ShapeParams& s : shapes) {
    double largest = 0.0;
    constexpr int kSteps = 180;
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; j < 2 * kSteps; ++j) {
        const double theta = M_PI * i / kSteps, phi = M_PI * j / kSteps;
        const Vec3 q(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
        largest = std::max(largest, 1.0 / std::sqrt(shape_g(GlyphShape::superquadric, s, q)));
      }
    EXPECT_LE(largest, 1.0 + 1e-9) << "α " << s.alpha << " β " << s.beta;
    EXPECT_GE(largest, 0.99) << "α " << s.alpha << " β " << s.beta;
  }
}

// Superquadrics of every proportion and sharpness, and signed glyphs of
// every sign pattern.
std::vector<std::pair<GlyphShape, ShapeParams>> sample_shapes() {
  std::vector<std::pair<GlyphShape, ShapeParams>> shapes;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.05, 1.0);
  for (int i = 0; i < 40; ++i) {
    const Vec3 radii(u(rng), u(rng), u(rng));
    const double sharpness = i % 2 ? 3.0 : 6.0;
    shapes.emplace_back(GlyphShape::superquadric, superquadric_params(radii, sharpness));
    const Vec3 signs(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    shapes.emplace_back(GlyphShape::signed_superquadric,
                        signed_params(radii, signs.cwiseProduct(radii), sharpness, SignConvention::tension_positive));
  }
  return shapes;
}

// The promises the tracer's bounds rest on, at random points of every
// direction and scale: g_e ≤ g (the bounding ellipsoid), u ≥ max|q_k| (the
// cube), u ≥ ‖q_⊥‖/ρ (the cylinder about the symmetry axis,
// support_cylinder_radius), u ≤ Lσ√g_e (the ball inside, whose entry proves F ≥ C:
// inner_level_g) and |∇u| ≤ Lσ in the stored frame (the rate of a source
// not yet reached), with the analytic gradient matching finite differences (a
// signed glyph's crease, where two branches meet, aside).
TEST(GlyphShapes, KeepTheBoundsTheTracerRestsOn) {
  std::mt19937 rng(11);
  std::normal_distribution<double> n;
  int gradients = 0, mismatched = 0;
  for (const auto& [shape, s] : sample_shapes()) {
    const double sigma = s.bound_scale;
    for (int i = 0; i < 400; ++i) {
      const Vec3 q = std::exp(n(rng)) * Vec3(n(rng), n(rng), n(rng));
      Vec3 grad;
      const double g = shape_g_gradient(shape, s, q, grad);
      const double g_e = q.squaredNorm();
      ASSERT_LE(g_e, g * (1.0 + 1e-9)) << "α " << s.alpha << " β " << s.beta;
      const double u = std::sqrt(g);
      ASSERT_GE(u * (1.0 + 1e-9), sigma * q.cwiseAbs().maxCoeff());
      Vec3 across = q;
      across[s.axis] = 0.0;
      ASSERT_GE(u * support_cylinder_radius(s) * (1.0 + 1e-9), sigma * across.norm())
          << "α " << s.alpha << " β " << s.beta;
      ASSERT_LE(u, sigma * s.lipschitz * std::sqrt(g_e) * (1.0 + 1e-9)) << "α " << s.alpha << " β " << s.beta;
      // ∇u = ∇g / (2u).
      ASSERT_LE(grad.norm() / (2.0 * u), sigma * s.lipschitz * (1.0 + 1e-9));
      for (int k = 0; k < 3; ++k) {
        const double h = 1e-6 * q.norm();
        Vec3 lo = q, hi = q;
        lo[k] -= h, hi[k] += h;
        const double numeric = (shape_g(shape, s, hi) - shape_g(shape, s, lo)) / (2 * h);
        ++gradients;
        if (std::fabs(grad[k] - numeric) > 1e-4 * (std::fabs(numeric) + grad.norm())) {
          ++mismatched;
          EXPECT_EQ(shape, GlyphShape::signed_superquadric) << "α " << s.alpha << " β " << s.beta;
        }
      }
    }
  }
  EXPECT_LT(mismatched, gradients / 1000);
}

// A source the tracer has not evaluated yet is bounded from where its span
// begins, the ray's entry into what holds its support (the bounding
// ellipsoid narrowed to the cube and the cylinder): u ≥ 1 − σ√a (t − t0)
// (shape_trace.cpp: span_rate), for every shape. A signed glyph's u
// changes up to 1.2 times as fast as that along a ray (its cones), yet the
// bound holds: u ≥ N, the superquadric's gauge, which is at least 1 at t0
// and 1-Lipschitz. (Not from where the ray enters the influence box,
// RaySpan::box_t0: at a signed glyph's cones only u ≥ 1 holds, and it
// fails there.) Along random rays through single glyphs of every
// proportion, sharpness and sign pattern, the spans a query collects.
TEST(GlyphShapes, ASourceNotYetEvaluatedFallsNoFasterThanItsRateFromItsEntry) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> n;
  int checked = 0;
  for (int glyph = 0; glyph < 60; ++glyph) {
    GlyphSource g;
    g.centre = Vec3::Zero();
    g.axes = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
    g.radii = Vec3(0.1 + u(rng), 0.1 + u(rng), 0.1 + u(rng));
    g.eigenvalues = Vec3(glyph & 1 ? 1 : -1, glyph & 2 ? 1 : -1, glyph & 4 ? 1 : -1).cwiseProduct(g.radii);
    for (const GlyphShape shape : {GlyphShape::superquadric, GlyphShape::signed_superquadric}) {
      const BlobField field = make_blob_field({g}, {{1.0f, 1.0f, 1.0f}}, 1.0, KernelKind::wyvill, Blend::sum, 0.5,
                                              shape, glyph % 2 ? 3.0 : 6.0);
      const EmbreeDevice device;
      const BlobGeometry blobs(device.get(), field, TraceSettings{});
      const double sigma = shape_params(field, 0).bound_scale;
      for (int r = 0; r < 40; ++r) {
        const Vec3 o = 4.0 * Vec3(n(rng), n(rng), n(rng)).normalized();
        const Vec3 d = (g.radii.maxCoeff() * Vec3(u(rng), u(rng), u(rng)) - 0.5 * Vec3::Ones() - o).normalized();
        FieldRay ray;
        const RayInterval whole{o, d, 0.0, 1e30};
        blobs.collect_spans(&whole, 1, &ray);
        for (const RaySpan& span : ray.spans) {
          const double rate = sigma * std::sqrt(span.a);
          for (int k = 0; k <= 200; ++k) {
            const double t = span.t0 + (span.t1 - span.t0) * k / 200.0;
            const double u_t = std::sqrt(source_g(field, 0, o + t * d));
            const double bound = 1.0 - rate * (t - span.t0);
            ASSERT_GE(u_t, bound - 1e-9) << glyph_shape_name(shape) << " glyph " << glyph << " ray " << r << " t " << t;
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 100000);
}

// The cylinder is the least about the axis, not only a bound: the glyph's
// equator reaches it (at 45° between its other axes, where the equatorial
// norm is smallest), so it cuts no more than it may and no less.
TEST(Superquadric, SupportCylinderTouchesTheEquator) {
  for (const auto& sample : sample_shapes()) {
    ShapeParams s = sample.second;
    s.pointed = 0;  // N itself: a signed glyph's points only raise u (u ≥ N)
    double largest = 0.0;
    for (int j = 0; j < 360; ++j) {
      Vec3 q = Vec3::Zero();
      q[(s.axis + 1) % 3] = std::cos(M_PI * j / 180.0), q[(s.axis + 2) % 3] = std::sin(M_PI * j / 180.0);
      largest = std::max(largest, 1.0 / std::sqrt(shape_g(GlyphShape::superquadric, s, q / double(s.bound_scale))));
    }
    EXPECT_LE(largest, support_cylinder_radius(s)) << "α " << s.alpha;
    EXPECT_GE(largest, support_cylinder_radius(s) * (1.0 - 1e-5)) << "α " << s.alpha;
  }
}

// superquadric_reach is the support's own extent along every direction a:
// no point of N = 1 reaches further, and Hölder's equality case, nested as
// N is, gives the point that reaches it (N(q*) = 1, a·q* = h(a)). Glyphs
// from round to sharp (sharpness 3 and 6).
TEST(Superquadric, ReachIsTheSupportsOwnAlongEveryDirection) {
  std::mt19937 rng(5);
  std::normal_distribution<double> n;
  // The unit p-norm vector that a·w = ‖a‖_{p*} picks (p* = dual), for a pair.
  const auto holder = [](double x, double y, double dual, double& wx, double& wy) {
    const double norm = std::pow(std::pow(std::fabs(x), dual) + std::pow(std::fabs(y), dual), 1.0 / dual);
    wx = std::copysign(std::pow(std::fabs(x) / norm, dual - 1.0), x);
    wy = std::copysign(std::pow(std::fabs(y) / norm, dual - 1.0), y);
    return norm;
  };
  for (const auto& sample : sample_shapes()) {
    ShapeParams s = sample.second;
    s.pointed = 0;
    const int z = s.axis, i = (z + 1) % 3, j = (z + 2) % 3;
    const double sigma = s.bound_scale;
    for (int k = 0; k < 50; ++k) {
      const Vec3 a(n(rng), n(rng), n(rng));
      const double reach = superquadric_reach(s, a);
      double wi, wj, e, wz;
      const double equator = holder(a[i], a[j], 2.0 / (2.0 - s.alpha), wi, wj);
      const double whole = holder(equator, a[z], 2.0 / (2.0 - s.beta), e, wz);
      Vec3 q;
      q[i] = e * wi, q[j] = e * wj, q[z] = wz;
      ASSERT_NEAR(shape_g(GlyphShape::superquadric, s, q / sigma), 1.0, 1e-9) << "α " << s.alpha << " β " << s.beta;
      ASSERT_NEAR(a.dot(q), whole, 1e-12 * whole);
      ASSERT_GE(reach, whole);
      ASSERT_LE(reach, whole * (1.0 + 2e-6));
      for (int m = 0; m < 40; ++m) {  // and no other point of the surface beyond it
        const Vec3 p = Vec3(n(rng), n(rng), n(rng));
        const Vec3 on = p / std::sqrt(shape_g(GlyphShape::superquadric, s, p / sigma));
        ASSERT_LE(a.dot(on), reach) << "α " << s.alpha << " β " << s.beta;
      }
    }
  }
}

// 60 glyphs of `shape` turned every way, of radii 0.05 to 1 and eigenvalues
// of either sign, scattered about the origin.
BlobField random_glyph_field(std::mt19937& rng, GlyphShape shape) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(0.05, 1.0);
  std::vector<GlyphSource> glyphs(60);
  for (GlyphSource& g : glyphs) {
    g.centre = Vec3(n(rng), n(rng), n(rng));
    g.axes = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
    g.radii = Vec3(u(rng), u(rng), u(rng));
    g.eigenvalues = g.radii.cwiseProduct(Vec3(n(rng), n(rng), n(rng)).cwiseSign());
  }
  return make_blob_field(glyphs, std::vector<std::array<float, 3>>(glyphs.size(), {1, 1, 1}), 1.5, KernelKind::wyvill,
                         Blend::sum, 0.5, shape, 4.0);
}

// A ray through a point of source i's support (u's draw of its way out),
// from any side, near or far, and its span; false where round-off leaves
// it none.
bool ray_through_support(const BlobField& field, std::size_t i, std::mt19937& rng, std::normal_distribution<double>& n,
                         std::uniform_real_distribution<double>& u, Vec3& o, Vec3& d, RaySpan& span) {
  const BlobSource& source = field.sources[i];
  const Vec3 c(source.centre[0], source.centre[1], source.centre[2]);
  const Vec3 x = c + shape_matrix(source).inverse() * (u(rng) * Vec3(n(rng), n(rng), n(rng)).normalized());
  o = x + std::exp(3.0 * n(rng)) * Vec3(n(rng), n(rng), n(rng)).normalized();
  d = (x - o).normalized();
  return ray_span(source, std::uint32_t(i), 0, o, d, 0.0, 1e9, span, source_support(field, i));
}

// Every point of every glyph's support, turned any way in the world, lies
// in its influence box (the tighter of the ellipsoid's and the support's
// own, and a signed glyph's cones'), and a ray through it collects a span that holds
// it: no part of a glyph is cut off by the bounds that make rays cheap.
TEST(GlyphShapes, InfluenceBoxesAndSpansHoldTheWholeSupport) {
  std::mt19937 rng(23);
  std::normal_distribution<double> n;
  for (GlyphShape shape : {GlyphShape::superquadric, GlyphShape::signed_superquadric}) {
    const BlobField field = random_glyph_field(rng, shape);
    int points = 0;
    for (std::size_t i = 0; i < field.sources.size(); ++i) {
      const BlobSource& source = field.sources[i];
      const Mat3 to_world = shape_matrix(source).inverse();
      const Vec3 c(source.centre[0], source.centre[1], source.centre[2]);
      const Box3 box = influence_bounds(field, i);
      const Vec3 slack = Vec3::Constant(1e-6 * box.diagonal());
      for (int k = 0; k < 300; ++k) {
        // A direction in the stored frame scaled onto g = 1, the support's edge.
        const Vec3 w = Vec3(n(rng), n(rng), n(rng)).normalized();
        const Vec3 x = c + to_world * (w / std::sqrt(shape_g(shape, shape_params(field, i), w)));
        ASSERT_TRUE((x.array() >= (box.lo - slack).array()).all() && (x.array() <= (box.hi + slack).array()).all())
            << glyph_shape_name(shape) << " source " << i;
        const Vec3 o = x + 4.0 * Vec3(n(rng), n(rng), n(rng)).normalized(), d = (x - o).normalized();
        const double t = (x - o).norm();
        RaySpan span;
        ASSERT_TRUE(ray_span(source, std::uint32_t(i), 0, o, d, 0.0, 100.0, span, source_support(field, i)))
            << glyph_shape_name(shape) << " source " << i;
        EXPECT_LE(span.t0, t * (1.0 + 1e-7));
        EXPECT_GE(span.t1, t * (1.0 - 1e-7));
        ++points;
      }
    }
    EXPECT_EQ(points, 60 * 300);
  }
}

// A signed glyph's box is also its double cones' (influence_bounds): never
// larger than the same glyph's as a superquadric, and much smaller for
// most glyphs with a point turned aslant, where the cube's corners stick
// out beyond the cones' sides. (The same draws make both fields: a point
// changes neither W_s nor σ.) It fails when the cones' boxes are left out.
TEST(GlyphShapes, SignedGlyphsBoxesAreTheirConesWhereTighter) {
  std::mt19937 rng_signed(41), rng_superquadric(41);
  const BlobField signed_field = random_glyph_field(rng_signed, GlyphShape::signed_superquadric);
  const BlobField superquadrics = random_glyph_field(rng_superquadric, GlyphShape::superquadric);
  int pointed = 0, tighter = 0;
  for (std::size_t i = 0; i < signed_field.sources.size(); ++i) {
    const Vec3 narrowed = influence_bounds(signed_field, i).size();
    const Vec3 plain = influence_bounds(superquadrics, i).size();
    ASSERT_TRUE((narrowed.array() <= plain.array()).all()) << "source " << i;
    if (!shape_params(signed_field, i).pointed) {
      EXPECT_EQ(narrowed, plain) << "source " << i;
      continue;
    }
    ++pointed;
    tighter += narrowed.prod() < 0.8 * plain.prod();
  }
  EXPECT_GT(pointed, 30);
  EXPECT_GT(tighter, pointed / 2);
}

// Each glyph of `field` that has a point: f(i, its shape, its source, W_s,
// its centre).
template <class F>
void for_each_pointed_glyph(const BlobField& field, F&& f) {
  for (std::size_t i = 0; i < field.sources.size(); ++i) {
    const ShapeParams& params = shape_params(field, i);
    if (!params.pointed) continue;
    const BlobSource& source = field.sources[i];
    f(i, params, source, shape_matrix(source), Vec3(source.centre[0], source.centre[1], source.centre[2]));
  }
}

// A signed glyph's span ends where the ray leaves the double cones about
// its points, and is dropped where it misses one (ray_span.cpp,
// clip_to_cone); its start stays the box's and cylinder's. No point of the
// glyph's support is cut off: every sample of the box's span with u < 1
// lies in the cones' span. The cones cut much, and where they end a span
// the ray is on a cone's side (C_k = 1). Rays through random glyphs'
// supports from every side and distance, and a quarter of them from a
// camera 10² to 10⁵ away (10³ to 10⁷ glyph sizes), where the cone's
// quadratic written about the ray's origin rounded its roots past the
// cone's widening.
TEST(GlyphShapes, SignedGlyphsSpansEndWhereTheyLeaveTheirPoints) {
  std::mt19937 rng(37);
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(0.05, 1.0), decades(2.0, 5.0);
  const BlobField field = random_glyph_field(rng, GlyphShape::signed_superquadric);
  int spans = 0, dropped = 0, shortened = 0, on_a_side = 0;
  for_each_pointed_glyph(field, [&](std::size_t i, const ShapeParams& params, const BlobSource& source, const Mat3& w,
                                    const Vec3& c) {
    ShapeSupport boxed = source_support(field, i);
    boxed.pointed = 0;
    const auto cones = [&](const Vec3& x) {  // the largest C_k, in the glyph's own frame
      const Vec3 q = double(params.bound_scale) * (w * (x - c));
      double most = 0.0;
      for (int k = 0; k < 3; ++k)
        if (params.pointed & (1u << k))
          most = std::max(most, std::hypot(q[(k + 1) % 3], q[(k + 2) % 3]) / kConeBase + std::fabs(q[k]));
      return most;
    };
    for (int k = 0; k < 100; ++k) {
      Vec3 o, d;
      RaySpan box_span, span;
      // Half the rays aimed at the support, half at its box's corners.
      if (!ray_through_support(field, i, rng, n, u, o, d, box_span)) continue;
      if (k % 2) {
        const Vec3 corner = c + w.inverse() * (boxed.box * Vec3(n(rng), n(rng), n(rng)).cwiseSign());
        d = (corner - o).normalized();
      }
      if (k % 4 >= 2) o -= std::pow(10.0, decades(rng)) * d;
      if (!ray_span(source, std::uint32_t(i), 0, o, d, 0.0, 1e9, box_span, boxed)) continue;
      ++spans;
      const bool enters = ray_span(source, std::uint32_t(i), 0, o, d, 0.0, 1e9, span, source_support(field, i));
      for (int s = 0; s <= 400; ++s) {
        // (The last sample at the box's end itself, which t0 + (t1 − t0) may round past.)
        const double t = std::min(box_span.t1, box_span.t0 + (box_span.t1 - box_span.t0) * s / 400.0);
        if (source_g(field, i, o + t * d) >= 1.0) continue;
        ASSERT_TRUE(enters) << "source " << i << " ray " << k << ": dropped, yet u < 1 at t " << t;
        ASSERT_LE(t, span.t1) << "source " << i << " ray " << k;
      }
      if (!enters) {
        ++dropped;
        continue;
      }
      ASSERT_EQ(span.t0, box_span.t0) << "source " << i << " ray " << k;
      ASSERT_LE(span.t1, box_span.t1) << "source " << i << " ray " << k;
      if (span.t1 < box_span.t1) {
        ++shortened;
        const double at_end = cones(o + span.t1 * d);
        EXPECT_GE(at_end, 1.0 - 1e-9) << "source " << i << " ray " << k;
        on_a_side += at_end < 1.0 + 1e-5;
      }
    }
  });
  EXPECT_GT(spans, 2000);
  EXPECT_GT(dropped, spans / 25);
  EXPECT_GT(shortened, spans / 2);
  // (Not every one: a ray along a cone's side is left to the others.)
  EXPECT_GT(on_a_side, shortened * 9 / 10);
}

// A span's lower bound of g (RaySpan::lower_a) is one: g never falls
// below it anywhere on the span, whatever the glyph and ray. And where it
// is taken from the box or the cylinder it is larger than the bounding
// ellipsoid's g_e all along the span: the proofs of the tracer get stronger,
// never weaker, and on rays over a sharp glyph's faces much stronger.
TEST(GlyphShapes, SpansLowerBoundOfGHoldsAndBeatsTheEllipsoids) {
  std::mt19937 rng(29);
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(0.05, 1.0);
  for (GlyphShape shape : {GlyphShape::superquadric, GlyphShape::signed_superquadric}) {
    const BlobField field = random_glyph_field(rng, shape);
    int spans = 0, tighter = 0;
    for (std::size_t i = 0; i < field.sources.size(); ++i) {
      const BlobSource& source = field.sources[i];
      const Mat3 w = shape_matrix(source);
      const Vec3 c(source.centre[0], source.centre[1], source.centre[2]);
      for (int k = 0; k < 200; ++k) {
        Vec3 o, d;
        RaySpan span;
        if (!ray_through_support(field, i, rng, n, u, o, d, span)) continue;
        ++spans;
        const auto lower = [&](double t) {
          return span.lower_a * (t - span.lower_t) * (t - span.lower_t) + span.lower_g;
        };
        double least_g_e = INFINITY;
        for (int j = 0; j <= 64; ++j) {
          const double t = span.t0 + (span.t1 - span.t0) * j / 64.0;
          const double g = shape_g(shape, shape_params(field, i), w * (o + t * d - c));
          ASSERT_LE(lower(t), g) << glyph_shape_name(shape) << " source " << i << " t " << t;
          least_g_e = std::min(least_g_e, span.g(t));
        }
        ASSERT_GE(span.least_lower_g(), std::min(span.g(peak_t(span)), least_g_e));
        if (span.least_lower_g() > 1.2 * span.g(peak_t(span)) + 0.01) ++tighter;
      }
    }
    EXPECT_GT(spans, 60 * 150) << glyph_shape_name(shape);
    // 0.29 of them for either shape (seed 29).
    EXPECT_GT(tighter, spans / 5) << glyph_shape_name(shape);
  }
}

// The least of a convex function over [lo, hi], by golden sections, in
// T's precision.
template <class T, class F>
T least_of_convex(F&& f, T lo, T hi) {
  for (int i = 0; i < 300 && hi - lo > std::numeric_limits<T>::epsilon() * (std::fabs(lo) + std::fabs(hi)); ++i) {
    const T m1 = lo + T(0.381966) * (hi - lo), m2 = hi - T(0.381966) * (hi - lo);
    if (f(m1) < f(m2)) hi = m2;
    else lo = m1;
  }
  return std::min({f(lo), f(hi), f(T(0.5) * (lo + hi))});
}

// A signed glyph's points bound its u from below along a ray: the least of
// each double cone C_k(q) = ‖q_⊥k‖/ρ + |q_k| over [lo, hi], in closed form
// (least_point_u), is the least golden sections find on that cone, and
// never above u's own least there. Rays through random glyphs' supports
// from every side, over spans begun part way (as an occlusion ray leaving
// a hit begins); on most of them the points say more than the span's box
// and cylinder.
TEST(GlyphShapes, SignedGlyphsPointsBoundUFromBelowAlongARay) {
  std::mt19937 rng(31);
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(0.05, 1.0);
  const BlobField field = random_glyph_field(rng, GlyphShape::signed_superquadric);
  int spans = 0, tighter = 0;
  for_each_pointed_glyph(field, [&](std::size_t i, const ShapeParams& params, const BlobSource&, const Mat3& w,
                                    const Vec3& c) {
    const double sigma = params.bound_scale;
    for (int k = 0; k < 100; ++k) {
      Vec3 o, d;
      RaySpan span;
      if (!ray_through_support(field, i, rng, n, u, o, d, span)) continue;
      ++spans;
      const double lo = span.t0 + (k % 2 ? 0.0 : u(rng) * (span.t1 - span.t0)), hi = span.t1;
      const Vec3 q0 = w * (o - c), v = w * d;
      const double least = least_point_u(params, q0, v, lo, hi);
      double cones = 0.0;
      for (int axis = 0; axis < 3; ++axis) {
        if (!(params.pointed & (1u << axis))) continue;
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        cones = std::max(cones, least_of_convex(
                                    [&](double t) {
                                      const Vec3 q = sigma * (q0 + t * v);
                                      return std::hypot(q[a], q[b]) / kConeBase + std::fabs(q[axis]);
                                    },
                                    lo, hi));
      }
      const double least_u = least_of_convex(
          [&](double t) { return std::sqrt(shape_g(GlyphShape::signed_superquadric, params, q0 + t * v)); }, lo, hi);
      // As tight as its margins for round-off (least_point_u) allow.
      const double reach =
          sigma * (q0.cwiseAbs().sum() + v.cwiseAbs().sum() * std::max(std::fabs(lo), std::fabs(hi)));
      ASSERT_GE(least, cones * (1.0 - 2e-9) - 2e-12 * reach) << "source " << i << " ray " << k;
      ASSERT_LE(least, least_u) << "source " << i << " ray " << k;
      if (least * least > 1.2 * span.least_lower_g() + 0.01) ++tighter;
    }
  });
  EXPECT_GT(spans, 2000);
  EXPECT_GT(tighter, spans / 2);
}

// least_point_u in closed form on the lines that try it hardest: through
// the cone's axis (where |P + t V| has a kink of its own), along its
// surface (α = m², the stationary point far out and flat), through its
// apex, and at scales from 10⁻⁵ to 10⁵. Against golden sections in long
// double: never above the least, and within 10⁻⁸ of it (relative to the
// line's reach). Round-off alone put the closed form's raw value up to
// 3·10⁻¹³ above the least; the quadratic form of |P + t V| (αt² + 2βt +
// γ, with D = αγ − β²) put it 4·10⁻⁹ above on a line near the axis.
TEST(GlyphShapes, LeastPointUHoldsWhereTheLineMeetsTheConeBadly) {
  std::mt19937 rng(5);
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ShapeParams params;
  params.pointed = 4;  // a double cone about q_2
  int tight = 0;
  for (int it = 0; it < 50000; ++it) {
    Vec3 q0(n(rng), n(rng), n(rng)), v(n(rng), n(rng), n(rng));
    double lo = -3.0 * u(rng), hi = lo + 6.0 * u(rng);
    switch (it % 5) {
      case 1:  // through the axis, nearly
        q0[0] = 2.0 * v[0] + 1e-9 * n(rng), q0[1] = 2.0 * v[1] + 1e-9 * n(rng);
        break;
      case 2: {  // along the cone's surface, nearly
        const double angle = 2.0 * M_PI * u(rng);
        v = Vec3(kConeBase * std::cos(angle), kConeBase * std::sin(angle), (it % 2 ? 1.0 : -1.0) + 1e-9 * n(rng));
        break;
      }
      case 3:  // from next to the apex
        q0 = Vec3(1e-9 * n(rng), 1e-9 * n(rng), 1.0);
        break;
      case 4: {  // far from unit scale
        q0 *= std::exp(4.0 * n(rng));
        v *= std::exp(4.0 * n(rng));
        const double along = (1.0 + q0.norm()) / v.norm();
        lo *= along, hi *= along;
        break;
      }
      default: break;
    }
    const double least = least_point_u(params, q0, v, lo, hi);
    const auto cone = [&](long double t) {
      const long double x = q0[0] + t * v[0], y = q0[1] + t * v[1], z = q0[2] + t * v[2];
      return std::sqrt(x * x + y * y) / (long double)kConeBase + std::fabs(z);
    };
    const long double reference = least_of_convex(cone, (long double)lo, (long double)hi);
    const double reach = q0.cwiseAbs().sum() + v.cwiseAbs().sum() * std::max(std::fabs(lo), std::fabs(hi));
    ASSERT_LE((long double)least, reference) << std::setprecision(17) << "line " << it;
    ASSERT_GE((long double)least, reference * (1.0L - 1e-8L) - 1e-8L * reach) << std::setprecision(17) << "line " << it;
    tight += (long double)least >= reference * (1.0L - 2e-9L);
  }
  EXPECT_GT(tight, 40000);
}

// Newton's entry and the tangent-line bounds need u convex along every
// ray: u(midpoint) ≤ the mean of u at the ends.
TEST(GlyphShapes, AreConvexAlongEveryRay) {
  std::mt19937 rng(13);
  std::normal_distribution<double> n;
  for (const auto& [shape, s] : sample_shapes())
    for (int i = 0; i < 400; ++i) {
      const Vec3 a(n(rng), n(rng), n(rng)), b(n(rng), n(rng), n(rng));
      const double mid = std::sqrt(shape_g(shape, s, 0.5 * (a + b)));
      ASSERT_LE(mid, 0.5 * (std::sqrt(shape_g(shape, s, a)) + std::sqrt(shape_g(shape, s, b))) + 1e-12);
    }
}

// A signed glyph points the axes that compress, under either convention,
// keeps every radius (u = 1 at each axis' end) and is sharper than the
// superquadric near a point, the same elsewhere.
// Many glyphs' shapes at once (their σ searches side by side in the
// gauge's lanes, spread over the cores) are each glyph's shape alone, to
// the bit: flat, long, round and sizeless glyphs, either sign.
TEST(GlyphShapes, ManyAtOnceAreEachAlone) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> size(0.01, 2.0), value(-3.0, 3.0);
  std::vector<Vec3> radii, eigenvalues;
  for (int i = 0; i < 203; ++i) {  // not a whole number of lane groups or chunks
    Vec3 r(size(rng), size(rng), size(rng));
    if (i % 17 == 0) r = Vec3::Zero();
    if (i % 13 == 1) r = Vec3(1.0, 1.0, 1.0);
    if (i % 11 == 2) r = Vec3(3.0, 0.1, 0.1);
    radii.push_back(r);
    eigenvalues.emplace_back(value(rng), value(rng), value(rng));
  }
  for (const GlyphShape shape : {GlyphShape::superquadric, GlyphShape::signed_superquadric}) {
    const std::vector<ShapeParams> many = shape_params(shape, radii, eigenvalues, 3.0, SignConvention::tension_positive);
    ASSERT_EQ(many.size(), radii.size());
    for (std::size_t i = 0; i < radii.size(); ++i) {
      const ShapeParams alone = shape == GlyphShape::superquadric
                                    ? superquadric_params(radii[i], 3.0)
                                    : signed_params(radii[i], eigenvalues[i], 3.0, SignConvention::tension_positive);
      const ShapeParams& a = many[i];
      EXPECT_TRUE(a.alpha == alone.alpha && a.beta == alone.beta && a.bound_scale == alone.bound_scale &&
                  a.axis == alone.axis && a.pointed == alone.pointed && a.lipschitz == alone.lipschitz)
          << glyph_shape_name(shape) << " glyph " << i << ": σ " << a.bound_scale << " against " << alone.bound_scale;
    }
  }
}

TEST(GlyphShapes, SignedGlyphPointsTheAxesThatCompress) {
  const Vec3 radii(1.0, 0.5, 0.25), eigenvalues(1.0, 0.5, -0.25);
  const ShapeParams mechanics = signed_params(radii, eigenvalues, 3.0, SignConvention::tension_positive);
  EXPECT_EQ(mechanics.pointed, 0b100);
  const ShapeParams soil = signed_params(radii, eigenvalues, 3.0, SignConvention::compression_positive);
  EXPECT_EQ(soil.pointed, 0b011);
  // A zero eigenvalue's noise points nothing.
  EXPECT_EQ(signed_params(radii, Vec3(1.0, -1e-9, 0.5), 3.0, SignConvention::tension_positive).pointed, 0);
  const ShapeParams plain = superquadric_params(radii, 3.0);
  const double sigma = plain.bound_scale;
  const auto u = [&](GlyphShape shape, const ShapeParams& s, const Vec3& q) {
    return std::sqrt(shape_g(shape, s, q / sigma));  // q in the glyph's own frame
  };
  for (int k = 0; k < 3; ++k) {
    const Vec3 end = Vec3::Unit(k);
    EXPECT_NEAR(u(GlyphShape::signed_superquadric, mechanics, end), 1.0, 1e-6);
  }
  const Vec3 near_point(0.3, 0.3, 0.9), near_face(0.9, 0.3, 0.05);
  EXPECT_GT(u(GlyphShape::signed_superquadric, mechanics, near_point),
            1.05 * u(GlyphShape::superquadric, plain, near_point));
  EXPECT_DOUBLE_EQ(u(GlyphShape::signed_superquadric, mechanics, near_face), u(GlyphShape::superquadric, plain, near_face));
}

Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

// A crowd of sharp, overlapping glyphs of every proportion (signed ones of
// every sign pattern).
BlobField superquadric_crowd(int count, double sharpness, Blend blend, GlyphShape shape = GlyphShape::superquadric) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<GlyphSource> glyphs;
  std::vector<std::array<float, 3>> colors;
  for (int i = 0; i < count; ++i) {
    GlyphSource g;
    g.centre = Vec3(u(rng), u(rng), u(rng)) - Vec3::Constant(0.5);
    g.axes = random_rotation(rng);
    g.radii = Vec3(0.1 + 0.3 * u(rng), 0.05 + 0.2 * u(rng), 0.03 + 0.1 * u(rng));
    g.eigenvalues = Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1).cwiseProduct(g.radii);
    glyphs.push_back(g);
    colors.push_back({1.0f, 1.0f, 1.0f});
  }
  return make_blob_field(glyphs, colors, 1.0, KernelKind::wyvill, blend, 0.5, shape, sharpness);
}

// A superquadric_crowd() of 30 glyphs of sharpness 3 and its span BVH,
// traced by sphere tracing (the only way for these shapes) with steps down
// to 10⁻⁷.
struct TracedCrowd {
  TracedCrowd(Blend blend, GlyphShape shape)
      : field(superquadric_crowd(30, 3.0, blend, shape)), blobs(device.get(), field, sphere_tracing()) {}
  static TraceSettings sphere_tracing() {
    TraceSettings settings;
    settings.intersector = Intersector::sphere;
    settings.min_step = 1e-7;
    return settings;
  }
  const BlobField field;
  const TraceSettings settings = sphere_tracing();
  const EmbreeDevice device;
  const BlobGeometry blobs;
};

// Every span a query collects ends in its source's influence box, and
// knows where the ray enters it (narrow_to_influence), however it is
// collected: the span BVH's
// traversal, which stops at the first entry it proves, and a list of
// nearby sources, which tests no source's own box, hold the same sources
// and give the same crossing to the bit. A shape's box is its support's
// own and a signed glyph's its cones', tighter than the bounds a span is
// cut from: spans that began before their boxes made the two disagree
// (fails without the narrowing).
TEST(GlyphShapes, ListedAndTraversedSpansAgreeInsideTheirBoxes) {
  for (const GlyphShape shape : {GlyphShape::superquadric, GlyphShape::signed_superquadric}) {
    SCOPED_TRACE(glyph_shape_name(shape));
    const TracedCrowd crowd(Blend::sum, shape);
    const BlobField& field = crowd.field;
    NearbySources list;
    std::vector<std::uint32_t> scratch;
    ASSERT_TRUE(crowd.blobs.gather_nearby(influence_bounds(field), field.sources.size(), list, scratch));
    std::mt19937 rng(47);
    std::uniform_real_distribution<double> u(-0.4, 0.4);
    std::normal_distribution<double> n;
    int spans = 0, hits = 0;
    for (int r = 0; r < 400; ++r) {
      const Vec3 o = r % 2 ? 3.0 * Vec3(n(rng), n(rng), n(rng)).normalized() : Vec3(u(rng), u(rng), u(rng));
      const Vec3 d = r % 2 ? (Vec3(u(rng), u(rng), u(rng)) - o).normalized() : Vec3(n(rng), n(rng), n(rng)).normalized();
      const RayInterval ray{o, d, 0.0, 8.0};
      std::vector<RaySpan> listed_spans;
      list.collect_spans(o, d, ray.tmin, ray.tmax, listed_spans);
      FieldRay gathered;
      crowd.blobs.collect_spans(&ray, 1, &gathered);
      for (const std::vector<RaySpan>* collected : {&listed_spans, &gathered.spans})
        for (const RaySpan& span : *collected) {
          const Box3 box = influence_bounds(field, span.source);
          const auto [entry, exit] = ray_interval_in(box, o, d, ray.tmin, ray.tmax);
          ASSERT_LE(span.t0, span.box_t0) << "ray " << r << " source " << span.source;
          ASSERT_LE(entry, span.box_t0) << "ray " << r << " source " << span.source;
          ASSERT_GE(exit, span.t1) << "ray " << r << " source " << span.source;
          ++spans;
        }
      TraceStats stats;
      FieldRay near, traversed;
      const double a = crowd.blobs.first_crossing_near(list, ray, near, stats, CrossingQuery::first);
      const double b = crowd.blobs.first_crossing_traversed(ray, traversed, stats, CrossingQuery::first);
      ASSERT_EQ(a, b) << "ray " << r;
      ASSERT_EQ(span_sources(near), span_sources(traversed)) << "ray " << r;
      hits += a >= 0.0;
    }
    EXPECT_GT(spans, 1000);
    EXPECT_GT(hits, 100);
  }
}

TEST(GlyphShapes, TracerFindsEveryCrossingDenseSamplingFinds) {
  for (const auto& [shape, blend] : {std::pair{GlyphShape::superquadric, Blend::sum}, {GlyphShape::superquadric, Blend::max},
                                     {GlyphShape::signed_superquadric, Blend::sum}, {GlyphShape::signed_superquadric, Blend::max}}) {
    SCOPED_TRACE(std::string(shape == GlyphShape::superquadric ? "superquadric " : "signed ") +
                 (blend == Blend::sum ? "sum" : "max"));
    const TracedCrowd crowd(blend, shape);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-0.4, 0.4);
    std::normal_distribution<double> n;
    int hits = 0, agreed = 0;
    for (int r = 0; r < 160; ++r) {
      // Half from outside the crowd towards it, half from inside it (as
      // shadow rays start), where sources are met half-way through.
      const Vec3 o = (r % 2 ? 3.0 * Vec3(n(rng), n(rng), n(rng)).normalized() : Vec3(u(rng), u(rng), u(rng)))
                         .cast<float>()
                         .cast<double>();
      const Vec3 d = (r % 2 ? Vec3(u(rng), u(rng), u(rng)) - o : Vec3(n(rng), n(rng), n(rng)))
                         .normalized()
                         .cast<float>()
                         .cast<double>();
      FieldRay ray;
      TraceStats stats;
      const RayInterval whole{o, d, 0.0, 1e30};
      crowd.blobs.collect_spans(&whole, 1, &ray);
      FieldRay occlusion;  // the same spans, for an occlusion query
      occlusion.spans = ray.spans;
      const double t =
          ray.spans.empty() ? -1.0 : ray.first_crossing(crowd.field, o, d, 0.0, 1e30, crowd.settings, stats);
      const double expected = sampled_crossing([&](double s) { return field_value(crowd.field, o + s * d); },
                                               crowd.field.isovalue, 6.0, 12000);
      if (expected >= 0.0) ++hits;
      // An occlusion query: blocked exactly when the ray crosses, at a
      // point inside the surface.
      TraceStats any_stats;
      const double any = occlusion.spans.empty()
                             ? -1.0
                             : occlusion.first_crossing(crowd.field, o, d, 0.0, 1e30, crowd.settings, any_stats,
                                                        CrossingQuery::any);
      EXPECT_EQ(any >= 0.0, t >= 0.0) << "ray " << r;
      if (any >= 0.0) {
        EXPECT_GE(field_value(crowd.field, o + any * d), crowd.field.isovalue * (1.0 - 1e-9)) << "ray " << r;
      }
      // A sliver thinner than a sample step (5e-4) can fall between
      // samples: then the tracer's crossing must be on the surface.
      if ((t < 0.0) != (expected < 0.0)) {
        ASSERT_GE(t, 0.0) << "ray " << r << ": dense sampling crosses at " << expected << ", the tracer misses";
        EXPECT_NEAR(field_value(crowd.field, o + t * d), crowd.field.isovalue, 1e-6) << "ray " << r;
        continue;
      }
      if (t < 0.0) continue;
      EXPECT_NEAR(t, expected, 1e-6) << "ray " << r;
      agreed += std::fabs(t - expected) <= 1e-6;
    }
    EXPECT_GT(hits, 40);
    EXPECT_GE(agreed, hits - 3);
  }
}

// A packet's rays walk side by side (FieldRay::start_crossing), their
// gauges in shared batches; ambient rays, each with its own spans, too.
// Each camera ray must get the bits it gets alone (its crossing, and the
// spans left for its shading: with groups, the hit group's), and each
// occlusion ray the same answer, blocked or free, at a point inside the
// surface (an `any` query returns the first it proves, which depends on
// the spans a packet's traversal stopped at). On a field with two groups,
// as hyperstreamlines' families make, and without. Sharing a lane's
// result with the wrong ray, or resuming one ray's walk from another's
// state, moves crossings or loses them.
TEST(GlyphShapes, RaysWalkedSideBySideAnswerAsEachAlone) {
  for (const GlyphShape shape : {GlyphShape::superquadric, GlyphShape::signed_superquadric})
    for (const bool grouped : {false, true}) {
      SCOPED_TRACE(std::string(shape == GlyphShape::superquadric ? "superquadric" : "signed") +
                   (grouped ? ", two groups" : ""));
      BlobField field = superquadric_crowd(40, 3.0, Blend::sum, shape);
      if (grouped)
        for (std::size_t i = 0; i < field.sources.size(); ++i) field.groups.push_back(std::uint8_t(i % 2));
      const EmbreeDevice device;
      const BlobGeometry blobs(device.get(), field, TracedCrowd::sphere_tracing());
      std::mt19937 rng(31);
      std::uniform_real_distribution<double> u(-0.4, 0.4);
      std::normal_distribution<double> n;
      int hits = 0, blocked = 0;
      for (int packet = 0; packet < 24; ++packet) {
        // From one eye towards the crowd, or (odd packets) from points
        // inside it in every direction, as occlusion rays leave.
        const Vec3 eye = 3.0 * Vec3(n(rng), n(rng), n(rng)).normalized();
        std::array<RayInterval, kMaxPacket> rays;
        for (RayInterval& ray : rays) {
          const Vec3 o = packet % 2 ? Vec3(u(rng), u(rng), u(rng)) : eye;
          const Vec3 d = packet % 2 ? Vec3(n(rng), n(rng), n(rng)) : Vec3(Vec3(u(rng), u(rng), u(rng)) - o);
          ray = {o.cast<float>().cast<double>(), d.normalized().cast<float>().cast<double>(), 0.0, 8.0};
        }
        for (const CrossingQuery query : {CrossingQuery::first, CrossingQuery::any}) {
          FieldRayLanes together, one_by_one;
          TraceStats stats;
          double packet_hits[kMaxPacket], own_hits[kMaxPacket];
          blobs.first_crossings(rays.data(), kMaxPacket, together.data(), stats, packet_hits, query);
          blobs.crossings_one_by_one(rays.data(), kMaxPacket, nullptr, one_by_one.data(), stats, own_hits, query);
          for (int i = 0; i < kMaxPacket; ++i) {
            const RayInterval& ray = rays[std::size_t(i)];
            FieldRay alone, traversed;
            double alone_hit;
            blobs.first_crossings(&ray, 1, &alone, stats, &alone_hit, query);
            const double traversed_hit = blobs.first_crossing_traversed(ray, traversed, stats, query);
            if (query == CrossingQuery::any) {
              ASSERT_EQ(packet_hits[i] >= 0.0, alone_hit >= 0.0) << "packet " << packet << " ray " << i;
              ASSERT_EQ(own_hits[i] >= 0.0, traversed_hit >= 0.0) << "packet " << packet << " ray " << i;
              for (const double t : {packet_hits[i], own_hits[i]}) {
                if (t < 0.0) continue;
                EXPECT_GE(field_value(field, ray.origin + t * ray.direction), field.isovalue * (1.0 - 1e-9))
                    << "packet " << packet << " ray " << i;
              }
              blocked += alone_hit >= 0.0;
              continue;
            }
            ASSERT_EQ(packet_hits[i], alone_hit) << "packet " << packet << " ray " << i;
            ASSERT_EQ(own_hits[i], traversed_hit) << "packet " << packet << " ray " << i;
            if (alone_hit < 0.0) continue;
            ++hits;
            const Vec3 normal = alone.surface_at(field, ray.origin, ray.direction, alone_hit).normal;
            EXPECT_EQ(together[std::size_t(i)].surface_at(field, ray.origin, ray.direction, alone_hit).normal, normal)
                << "packet " << packet << " ray " << i;
            EXPECT_EQ(one_by_one[std::size_t(i)].surface_at(field, ray.origin, ray.direction, alone_hit).normal,
                      traversed.surface_at(field, ray.origin, ray.direction, alone_hit).normal)
                << "packet " << packet << " ray " << i;
          }
        }
      }
      EXPECT_GT(hits, 60);
      EXPECT_GT(blocked, 60);
    }
}

// The renderer keeps one tracer per lane for ray after ray: nothing one
// ray learned may carry over to the next. One tracer reused for rays of
// every kind (from outside the crowd and from inside it, first crossings
// and `any` queries, in both orders) answers each as a fresh one does, to
// the bit. (A signed glyph's floors from its points, kept from a ray
// settled early for the next one, freed rays the glyphs block.)
TEST(GlyphShapes, ATracerKeepsNothingOfTheRayBefore) {
  for (const GlyphShape shape : {GlyphShape::superquadric, GlyphShape::signed_superquadric}) {
    SCOPED_TRACE(glyph_shape_name(shape));
    const TracedCrowd crowd(Blend::sum, shape);
    std::mt19937 rng(41);
    std::uniform_real_distribution<double> u(-0.4, 0.4);
    std::normal_distribution<double> n;
    FieldRay reused;
    int hits = 0, misses = 0;
    for (int r = 0; r < 600; ++r) {
      const Vec3 o = r % 3 ? 3.0 * Vec3(n(rng), n(rng), n(rng)).normalized() : Vec3(u(rng), u(rng), u(rng));
      const Vec3 d = r % 3 == 2 ? Vec3(n(rng), n(rng), n(rng)).normalized()
                                : (Vec3(u(rng), u(rng), u(rng)) - o).normalized();
      const CrossingQuery query = r % 2 ? CrossingQuery::any : CrossingQuery::first;
      const RayInterval ray{o, d, 0.0, 1e30};
      const auto answer = [&](FieldRay& tracer) {
        TraceStats stats;
        crowd.blobs.collect_spans(&ray, 1, &tracer);
        return tracer.spans.empty() ? -1.0
                                    : tracer.first_crossing(crowd.field, o, d, 0.0, 1e30, crowd.settings, stats, query);
      };
      FieldRay fresh;
      const double expected = answer(fresh), got = answer(reused);
      ASSERT_EQ(std::memcmp(&got, &expected, sizeof got), 0) << "ray " << r << ": " << got << " against " << expected;
      (expected >= 0.0 ? hits : misses) += 1;
    }
    EXPECT_GT(hits, 150);
    EXPECT_GT(misses, 150);
  }
}

// An occlusion ray that leaves a glyph hit starts its walk from the hit's
// tangent planes (support_planes.h) instead of evaluating the sources
// around its start: the same answer for every ray, blocked or not, with
// fewer gauges. A plane placed wrongly (its offset from the hit taken the
// wrong way, or a gradient not the source's) overstates how far the
// sources stay below C, and rays that the sources block come out free.
// The planes also rule out sources the ray cannot enter before their
// exact entries are sought (first_shape_entry): a union's answer is its
// first entry alone, so there a source ruled out wrongly frees a ray it
// blocks.
TEST(GlyphShapes, OcclusionRaysFromAHitAnswerTheSameFromItsPlanes) {
  for (const auto& [shape, blend] : {std::pair{GlyphShape::superquadric, Blend::sum}, {GlyphShape::superquadric, Blend::max},
                                     {GlyphShape::signed_superquadric, Blend::sum}, {GlyphShape::signed_superquadric, Blend::max}}) {
    SCOPED_TRACE(std::string(shape == GlyphShape::superquadric ? "superquadric " : "signed ") +
                 (blend == Blend::sum ? "sum" : "max"));
    const TracedCrowd crowd(blend, shape);
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(-0.4, 0.4);
    std::normal_distribution<double> n;
    int hit_points = 0, blocked = 0, free = 0;
    std::uint64_t gauges_without = 0, gauges_with = 0, probes_without = 0, probes_with = 0;
    for (int r = 0; r < 60; ++r) {
      const Vec3 o = 3.0 * Vec3(n(rng), n(rng), n(rng)).normalized();
      const Vec3 d = (Vec3(u(rng), u(rng), u(rng)) - o).normalized();
      FieldRay camera;
      TraceStats stats;
      const RayInterval whole{o, d, 0.0, 1e30};
      crowd.blobs.collect_spans(&whole, 1, &camera);
      const double t =
          camera.spans.empty() ? -1.0 : camera.first_crossing(crowd.field, o, d, 0.0, 1e30, crowd.settings, stats);
      if (t < 0.0) continue;
      ++hit_points;
      SupportPlanes planes;
      const Vec3 normal = camera.surface_at(crowd.field, o, d, t, &planes).normal;
      ASSERT_FALSE(planes.planes.empty());
      // From a shadow offset off the surface, in every direction of the
      // open side: into the crowd and out of it.
      const Vec3 start = o + t * d + 1e-4 * normal;
      for (int k = 0; k < 12; ++k) {
        Vec3 w = Vec3(n(rng), n(rng), n(rng)).normalized();
        if (w.dot(normal) < 0.0) w = -w;
        const RayInterval ray{start, w, 0.0, 1e30};
        FieldRay without, with;
        crowd.blobs.collect_spans(&ray, 1, &without);
        if (without.spans.empty()) continue;
        with.spans = without.spans;
        TraceStats stats_without, stats_with;
        const auto blocks = [&](FieldRay& tracer, TraceStats& counts) {
          return tracer.first_crossing(crowd.field, start, w, 0.0, 1e30, crowd.settings, counts, CrossingQuery::any) >=
                 0.0;
        };
        const bool by_evaluating = blocks(without, stats_without);
        with.leave_surface(&planes);
        const bool by_planes = blocks(with, stats_with);
        EXPECT_EQ(by_planes, by_evaluating) << "camera ray " << r << ", occlusion ray " << k;
        (by_evaluating ? blocked : free) += 1;
        gauges_without += stats_without.kernel_evaluations;
        gauges_with += stats_with.kernel_evaluations;
        probes_without += stats_without.field_evaluations;
        probes_with += stats_with.field_evaluations;
      }
    }
    EXPECT_GT(hit_points, 20);
    EXPECT_GT(blocked, 50);
    EXPECT_GT(free, 50);
    // (A union's occlusion ray evaluates no kernel: its entries are its
    // answer, each found by Newton's method, a field evaluation.)
    if (blend == Blend::sum) {
      EXPECT_LT(gauges_with, gauges_without);
    }
    EXPECT_LT(probes_with, probes_without);
  }
}

}  // namespace
}  // namespace hsb
