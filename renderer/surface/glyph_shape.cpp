#include "renderer/surface/glyph_shape.h"

#include "field/tensor/tensor_measures.h"
#include "renderer/surface/superquadric_gauge.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>

namespace hsb {

namespace {

// Lane i of `lanes` for the glyph `s` at q (its own frame): the point by
// role (a, b equatorial, z the symmetry axis) and Kindlmann's α and β.
void fill_lane(GaugeLanes& lanes, int i, const ShapeParams& s, const Vec3& q) {
  const int z = s.axis, a = (z + 1) % 3, b = (z + 2) % 3;
  lanes.qa[i] = q[a], lanes.qb[i] = q[b], lanes.qz[i] = q[z];
  lanes.alpha[i] = s.alpha, lanes.beta[i] = s.beta;
}

// N and ∇N from lane i, in the glyph's axis order; then the signed glyph's
// points where it has them. Returned by value and inlined, the axis order
// chosen by selects, not stores at a computed index: ∇N written through a
// pointer an element at a time and read back as a vector for the rate's
// dot product stalled on store forwarding (half the batch loop's time).
struct Gauge {
  double n;
  Vec3 gradient;
};
[[gnu::always_inline]] inline Gauge finish_lane(const GaugeLanes& lanes, int i, const ShapeParams& s, const Vec3& q) {
  const double da = lanes.da[i], db = lanes.db[i], dz = lanes.dz[i];
  Gauge g{lanes.n[i], s.axis == 0 ? Vec3(dz, da, db) : s.axis == 1 ? Vec3(db, dz, da) : Vec3(da, db, dz)};
  if (!s.pointed) return g;
  for (int k = 0; k < 3; ++k) {
    if (!(s.pointed & (1u << k))) continue;
    const int i1 = (k + 1) % 3, j = (k + 2) % 3;
    const double across = std::sqrt(q[i1] * q[i1] + q[j] * q[j]);  // q is O(1): no overflow to guard
    const double cone = across / kConeBase + std::fabs(q[k]);
    if (cone <= g.n) continue;
    g.n = cone;
    g.gradient = Vec3::Zero();
    if (across > 0.0) g.gradient[i1] = q[i1] / (across * kConeBase), g.gradient[j] = q[j] / (across * kConeBase);
    g.gradient[k] = std::copysign(1.0, q[k]);
  }
  return g;
}

// The superquadric gauge N at q (the glyph's own scaled frame) and ∇N, with
// the signed glyph's points where it has them.
double superquadric_gauge(const ShapeParams& s, const Vec3& q, Vec3* gradient) {
  GaugeLanes lanes;
  fill_lane(lanes, 0, s, q);
  superquadric_gauges(lanes, 1);
  const Gauge g = finish_lane(lanes, 0, s, q);
  if (gradient) *gradient = g.gradient;
  return g.n;
}

// The gauges of `count` samples, kGaugeLanes at a time: use(i, N, ∇N) for
// sample i, with N and ∇N at σ q_s (the glyph's own frame).
template <class Use>
void gauge_batches(const ShapeSample* samples, int count, Use&& use) {
  GaugeLanes lanes;
  Vec3 q[kGaugeLanes];
  for (int first = 0; first < count; first += kGaugeLanes) {
    const int n = std::min(kGaugeLanes, count - first);
    for (int i = 0; i < n; ++i) {
      const ShapeSample& sample = samples[first + i];
      q[i] = double(sample.params->bound_scale) * sample.q_s;
      fill_lane(lanes, i, *sample.params, q[i]);
    }
    superquadric_gauges(lanes, n);
    for (int i = 0; i < n; ++i) {
      const Gauge g = finish_lane(lanes, i, *samples[first + i].params, q[i]);
      use(first + i, g.n, g.gradient);
    }
  }
}

// σ = max |q|/N(q) = 1/min N over the unit sphere. For fixed
// |(q_a, q_b)| = ρ the equatorial p-norm (p = 2/α ≥ 2) is smallest at
// |q_a| = |q_b|, where it is c ρ with c = 2^{1/p − 1/2}; what is left is
// the smallest ‖(c cos θ, sin θ)‖_r, r = 2/β ≥ 2, over θ ∈ [0, π/2]: the
// least r-norm on the ellipse (x/c)² + y² = 1. At the ends it is c and 1;
// inside, Lagrange's condition x^{r−1}/(x/c²) = y^{r−1}/y puts the only
// critical point at y = x c^{2/(r−2)} (r > 2), where
// x = (1/c² + c^{4/(r−2)})^{−1/2} and the norm is x (1 + c^{2r/(r−2)})^{1/r}.
// The least of the three, in closed form, where a sampled search took 145
// gauges a glyph (two thirds of a superquadric glyph field's preparing).
// Rounded up by 10⁻⁶ so the bound holds to float precision.
float bound_scale(const ShapeParams& s) {
  const double r = 2.0 / double(s.beta), c = std::pow(2.0, 0.5 * double(s.alpha) - 0.5);
  double least = std::min(c, 1.0);
  if (r > 2.0) {
    const double x = 1.0 / std::sqrt(1.0 / (c * c) + std::pow(c, 4.0 / (r - 2.0)));
    least = std::min(least, x * std::pow(1.0 + std::pow(c, 2.0 * r / (r - 2.0)), 1.0 / r));
  }
  return float((1.0 + 1e-6) / least);
}

// Kindlmann's exponents and axis for the radii (superquadric_params without σ).
ShapeParams superquadric_exponents(const Vec3& radii, double sharpness) {
  std::array<int, 3> order{0, 1, 2};  // radii from largest to smallest
  std::sort(order.begin(), order.end(), [&](int i, int j) { return radii[i] > radii[j]; });
  ShapeParams s;
  const WestinMeasures w = westin_measures(radii);
  const double cl = std::min(0.99, w.linear), cp = std::min(0.99, w.planar);
  const double linear = std::pow(1.0 - cl, sharpness), planar = std::pow(1.0 - cp, sharpness);
  if (cl > cp) {
    s.axis = std::uint8_t(order[0]);
    s.alpha = float(planar);
    s.beta = float(linear);
  } else {
    s.axis = std::uint8_t(order[2]);
    s.alpha = float(linear);
    s.beta = float(planar);
  }
  return s;
}

// The signed glyph's points, on `s`.
void add_points(ShapeParams& s, const Vec3& eigenvalues, SignConvention sign) {
  const double largest = eigenvalues.cwiseAbs().maxCoeff();
  for (int k = 0; k < 3; ++k)
    if (is_compressive(eigenvalues[k], sign) && std::fabs(eigenvalues[k]) > 1e-3 * largest)
      s.pointed |= std::uint8_t(1u << k);
  if (s.pointed) s.lipschitz = float(std::sqrt(1.0 + 1.0 / (kConeBase * kConeBase)) * (1.0 + 1e-6));
}

}  // namespace

const char* glyph_shape_name(GlyphShape shape) {
  switch (shape) {
    case GlyphShape::ellipsoid: return "ellipsoid";
    case GlyphShape::superquadric: return "superquadric";
    case GlyphShape::signed_superquadric: return "signed";
  }
  return "?";
}

double shape_g(GlyphShape shape, const ShapeParams& params, const Vec3& q_s) {
  if (shape == GlyphShape::ellipsoid) return q_s.squaredNorm();
  const double n = superquadric_gauge(params, double(params.bound_scale) * q_s, nullptr);
  return n * n;
}

void shape_g_gradients(GlyphShape shape, const ShapeSample* samples, int count, double* g, Vec3* gradient) {
  if (shape == GlyphShape::ellipsoid) {
    for (int i = 0; i < count; ++i) {
      gradient[i] = 2.0 * samples[i].q_s;
      g[i] = samples[i].q_s.squaredNorm();
    }
    return;
  }
  // g = N(σ q_s)², so ∇g = 2 N ∇N · σ.
  gauge_batches(samples, count, [&](int i, double n, const Vec3& dn) {
    gradient[i] = (2.0 * double(samples[i].params->bound_scale) * n) * dn;
    g[i] = n * n;
  });
}

double shape_g_gradient(GlyphShape shape, const ShapeParams& params, const Vec3& q_s, Vec3& gradient) {
  const ShapeSample sample{&params, q_s, Vec3::Zero()};
  double g;
  shape_g_gradients(shape, &sample, 1, &g, &gradient);
  return g;
}

void shape_u_rates(GlyphShape shape, const ShapeSample* samples, int count, double* u, double* du_dt) {
  if (shape == GlyphShape::ellipsoid) {
    for (int i = 0; i < count; ++i) {
      const Vec3 &q = samples[i].q_s, &v = samples[i].v_s;
      u[i] = q.norm();
      du_dt[i] = u[i] > 0.0 ? q.dot(v) / u[i] : -v.norm();
    }
    return;
  }
  // u = N(σ q_s): du/dt = σ ∇N · v_s.
  gauge_batches(samples, count, [&](int i, double n, const Vec3& dn) {
    u[i] = n;
    du_dt[i] = double(samples[i].params->bound_scale) * dn.dot(samples[i].v_s);
  });
}

double shape_u_rate(GlyphShape shape, const ShapeParams& params, const Vec3& q_s, const Vec3& v_s, double& du_dt) {
  const ShapeSample sample{&params, q_s, v_s};
  double u;
  shape_u_rates(shape, &sample, 1, &u, &du_dt);
  return u;
}

double shape_entry(GlyphShape shape, const ShapeParams& params, const Vec3& q0, const Vec3& v, double u_level,
                   double lo, double hi) {
  double t = lo, last_step = INFINITY;
  for (int i = 0; i < 60; ++i) {
    double slope;
    const double excess = shape_u_rate(shape, params, q0 + t * v, v, slope) - u_level;
    if (excess <= 0.0) return t;
    if (slope >= 0.0) return -1.0;
    const double next = t - excess / slope;
    if (next > hi) return -1.0;
    // Converged: the root lies within round-off of next. Or Newton's own
    // regime has begun, each error about K times the last one squared:
    // a step below a hundredth of the one before says K e ≤ 1/100, so
    // next's error, K e², is a ten-thousandth of a step that is itself
    // below 10⁻⁸ of t, and the gauge evaluation that would confirm it
    // (a quarter of a union of superquadrics' entries) is left out.
    const double step = next - t, scale = std::fabs(t) + std::fabs(next);
    if (step <= 1e-13 * scale || excess <= 1e-13 * u_level || (step <= 1e-8 * scale && step <= 1e-2 * last_step))
      return next;
    t = next;
    last_step = step;
  }
  return -1.0;  // not settled: no bound from this source, which is always safe
}

namespace {
// The least of C(t) = |P + t V|/ρ + |a + t b| over [lo, hi]: the double
// cone along the line, P, V the part across its axis and a, b the part
// along it. C is convex, so its least over [lo, hi] is at its least over
// the line, t*, clamped into [lo, hi]. t* is the kink t_k = −a/b of
// |a + t b| where C's slopes on either side of it have opposite signs;
// else it lies on the side whose slope there says C falls, s = sign(a +
// t b), where h(t) = |P + t V| = √(αt² + 2βt + γ) has h' = (αt + β)/h =
// m, m = −s b ρ, which solves to αt + β = m √(D/(α − m²)), D = αγ − β²
// (|m| < √α there, as h' passes from that slope to m).
double least_cone(double px, double py, double vx, double vy, double a, double b, double lo, double hi) {
  const double alpha = vx * vx + vy * vy, beta = px * vx + py * vy;
  // |P + t V|, from its parts: the quadratic's own cancellation where the
  // line passes near the axis cost nine digits.
  const auto h = [&](double t) {
    const double x = px + t * vx, y = py + t * vy;
    return std::sqrt(x * x + y * y);
  };
  // D = αγ − β² = (P × V)², Lagrange's identity, without its cancellation.
  const double cross = std::fabs(px * vy - py * vx);
  const auto stationary = [&](double m) { return (m * cross / std::sqrt(alpha - m * m) - beta) / alpha; };
  double t = lo;
  if (b == 0.0) {
    if (alpha > 0.0) t = -beta / alpha;  // where h is least
  } else {
    t = -a / b;
    const double at_kink = h(t);
    if (at_kink > 0.0) {
      const double slope = (alpha * t + beta) / (at_kink * kConeBase);  // h'/ρ at the kink
      if (slope + std::fabs(b) < 0.0) t = stationary(-std::fabs(b) * kConeBase);  // falls beyond the kink
      else if (slope - std::fabs(b) > 0.0) t = stationary(std::fabs(b) * kConeBase);  // rises before it
    }
  }
  t = std::clamp(t, lo, hi);
  return h(t) / kConeBase + std::fabs(a + t * b);
}
}  // namespace

double least_point_u(const ShapeParams& params, const Vec3& q0, const Vec3& v, double lo, double hi) {
  if (!params.pointed || !(lo <= hi)) return 0.0;
  // In the glyph's own frame q = σ q_s, where the cones are.
  const double sigma = params.bound_scale;
  const Vec3 q = sigma * q0, w = sigma * v;
  double least = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (!(params.pointed & (1u << k))) continue;
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    least = std::max(least, least_cone(q[i], q[j], w[i], w[j], q[k], w[k], lo, hi));
  }
  // Rounded down: C at the computed t* is within round-off of the least,
  // at most 3·10⁻¹³ of it and 3·10⁻¹⁶ of the line's reach in q
  // (GlyphShapes.LeastPointUHoldsWhereTheLineMeetsTheConeBadly), so
  // margins of 10⁻⁹ and 10⁻¹² are ample.
  const double reach = q.cwiseAbs().sum() + w.cwiseAbs().sum() * std::max(std::fabs(lo), std::fabs(hi));
  return std::max(0.0, least * (1.0 - 1e-9) - 1e-12 * reach);
}

double support_cylinder_radius(const ShapeParams& params) {
  return (1.0 + 1e-6) * std::pow(2.0, 0.5 * std::max(0.0, 1.0 - double(params.alpha)));
}

namespace {
// ‖(x, y)‖_p for p ≥ 1, its larger term divided out so that no power
// under- or overflows.
double pair_norm(double x, double y, double p) {
  const double largest = std::max(std::fabs(x), std::fabs(y));
  if (largest == 0.0) return 0.0;
  return largest * std::pow(std::pow(std::fabs(x) / largest, p) + std::pow(std::fabs(y) / largest, p), 1.0 / p);
}
}  // namespace

double superquadric_reach(const ShapeParams& params, const Vec3& a) {
  const int z = params.axis, i = (z + 1) % 3, j = (z + 2) % 3;
  const double equator = pair_norm(a[i], a[j], 2.0 / (2.0 - double(params.alpha)));
  return (1.0 + 1e-6) * pair_norm(equator, a[z], 2.0 / (2.0 - double(params.beta)));
}

ShapeParams signed_params(const Vec3& radii, const Vec3& eigenvalues, double sharpness, SignConvention sign) {
  ShapeParams s = superquadric_params(radii, sharpness);
  add_points(s, eigenvalues, sign);
  return s;
}

ShapeParams superquadric_params(const Vec3& radii, double sharpness) {
  if (!(radii.sum() > 0.0)) return ShapeParams{};
  ShapeParams s = superquadric_exponents(radii, sharpness);
  s.bound_scale = bound_scale(s);
  return s;
}

std::vector<ShapeParams> shape_params(GlyphShape shape, const std::vector<Vec3>& radii,
                                      const std::vector<Vec3>& eigenvalues, double sharpness, SignConvention sign) {
  std::vector<ShapeParams> shapes(radii.size());
  tbb::parallel_for(std::size_t{0}, radii.size(), [&](std::size_t i) {
    if (radii[i].sum() > 0.0) {
      shapes[i] = superquadric_exponents(radii[i], sharpness);
      shapes[i].bound_scale = bound_scale(shapes[i]);
    }
    if (shape == GlyphShape::signed_superquadric) add_points(shapes[i], eigenvalues[i], sign);
  });
  return shapes;
}

}  // namespace hsb
