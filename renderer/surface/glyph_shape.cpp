#include "renderer/surface/glyph_shape.h"

#include "field/tensor/tensor_measures.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <cmath>

namespace hsb {

namespace {

// r^e for r in [0, 1], e ≥ 1, or 0 where r^e < 2⁻⁶⁴. Such a term leaves a
// sum with a term of 1 unchanged, and its part of the gradient is below the
// larger's last bit; yet pow would spend its time on it, twice over where
// it underflows, and sharp glyphs raise most ratios to exponents in the
// tens or hundreds. log₂ r is below both e₂ + 1 (e₂ its binary exponent)
// and (r − 1)/ln 2.
double power_below_one(double r, double e) {
  std::uint64_t bits;
  std::memcpy(&bits, &r, sizeof bits);
  const int exponent = int((bits >> 52) & 0x7ff) - 1023;
  const double log2_above = std::min(double(exponent + 1), (r - 1.0) * M_LOG2E);
  if (e * log2_above <= -64.0) return 0.0;
  return std::exp2(e * std::log2(r));
}

// ‖(x, y)‖_p for p ≥ 2 (its reciprocal given too) and its partial
// derivatives, each in [−1, 1]. The terms are divided by the larger one
// first: |x|^p for p = 2·10⁶ would overflow or vanish, (|x|/m)^p is 1 for
// the larger term and harmless for the other.
struct PNorm {
  double value = 0.0, dx = 0.0, dy = 0.0;
};
PNorm p_norm(double x, double y, double p, double inv_p) {
  const double ax = std::fabs(x), ay = std::fabs(y), m = std::max(ax, ay);
  if (m == 0.0) return {};
  // pow takes most of a superquadric's time: the larger term's power is
  // exactly 1, the smaller's is skipped where it would underflow, and each
  // power comes with its derivative's, without dividing:
  //   r^{p−1} = ∂‖·‖/∂(smaller) / (∂‖·‖/∂(larger)),
  //   ‖·‖ = m · S^{1/p} and ∂‖·‖/∂(larger) = S^{1/p − 1}, S = 1 + r^p.
  const double small = std::min(ax, ay), r = small / m;
  const double slope_ratio = r > 0.0 ? power_below_one(r, p - 1.0) : 0.0;
  const double sum = 1.0 + slope_ratio * r;  // in [1, 2]
  const double d_large = slope_ratio > 0.0 ? std::exp2((inv_p - 1.0) * std::log2(sum)) : 1.0;
  PNorm n;
  n.value = m * (d_large * sum);
  const double d_small = slope_ratio * d_large;
  const bool x_large = ax == m;
  n.dx = std::copysign(x_large ? d_large : d_small, x);
  n.dy = std::copysign(x_large ? d_small : d_large, y);
  return n;
}

// The superquadric gauge N at q (the glyph's own scaled frame) and ∇N, with
// the signed glyph's points where it has them.
double superquadric_gauge(const ShapeParams& s, const Vec3& q, Vec3* gradient) {
  const int z = s.axis, a = (z + 1) % 3, b = (z + 2) % 3;
  const double alpha = s.alpha, beta = s.beta;
  const PNorm equator = p_norm(q[a], q[b], 2.0 / alpha, 0.5 * alpha);
  const PNorm whole = p_norm(equator.value, q[z], 2.0 / beta, 0.5 * beta);
  if (gradient) {
    (*gradient)[a] = whole.dx * equator.dx;
    (*gradient)[b] = whole.dx * equator.dy;
    (*gradient)[z] = whole.dy;
  }
  double n = whole.value;
  for (int k = 0; k < 3; ++k) {
    if (!(s.pointed & (1u << k))) continue;
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double across = std::sqrt(q[i] * q[i] + q[j] * q[j]);  // q is O(1): no overflow to guard
    const double cone = across / kConeBase + std::fabs(q[k]);
    if (cone <= n) continue;
    n = cone;
    if (gradient) {
      Vec3 g = Vec3::Zero();
      if (across > 0.0) g[i] = q[i] / (across * kConeBase), g[j] = q[j] / (across * kConeBase);
      g[k] = std::copysign(1.0, q[k]);
      *gradient = g;
    }
  }
  return n;
}

// σ = max |q|/N(q) = 1/min N over the unit sphere. For fixed |(q_a, q_b)| = ρ
// the equatorial p-norm (p ≥ 2) is smallest at |q_a| = |q_b|, where it is
// c ρ with c = 2^{1/p − 1/2}; what is left is the smallest ‖(c cos θ,
// sin θ)‖_r over θ ∈ [0, π/2]: sampled, then refined between the best
// sample's neighbours, and σ rounded up by 10⁻⁶ so the bound holds to
// float precision.
double superquadric_bound_scale(double alpha, double beta) {
  const double p = 2.0 / alpha, r = 2.0 / beta, c = std::pow(2.0, 1.0 / p - 0.5);
  const auto gauge = [&](double theta) { return p_norm(c * std::cos(theta), std::sin(theta), r, 0.5 * beta).value; };
  constexpr int kSamples = 64;
  const double step = 0.5 * M_PI / kSamples;
  int best = 0;
  double least = gauge(0.0);
  for (int i = 1; i <= kSamples; ++i)
    if (const double n = gauge(i * step); n < least) least = n, best = i;
  double lo = std::max(0, best - 1) * step, hi = std::min(kSamples, best + 1) * step;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 40; ++i) {
    const double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
    const double na = gauge(a), nb = gauge(b);
    least = std::min({least, na, nb});
    if (na < nb) hi = b;
    else lo = a;
  }
  return (1.0 + 1e-6) / least;
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

double shape_g_gradient(GlyphShape shape, const ShapeParams& params, const Vec3& q_s, Vec3& gradient) {
  if (shape == GlyphShape::ellipsoid) {
    gradient = 2.0 * q_s;
    return q_s.squaredNorm();
  }
  // g = N(σ q_s)², so ∇g = 2 N ∇N · σ.
  const double sigma = params.bound_scale;
  Vec3 dn;
  const double n = superquadric_gauge(params, sigma * q_s, &dn);
  gradient = (2.0 * sigma * n) * dn;
  return n * n;
}

double shape_u_rate(GlyphShape shape, const ShapeParams& params, const Vec3& q_s, const Vec3& v_s, double& du_dt) {
  if (shape == GlyphShape::ellipsoid) {
    const double u = q_s.norm();
    du_dt = u > 0.0 ? q_s.dot(v_s) / u : -v_s.norm();
    return u;
  }
  // u = N(σ q_s): du/dt = σ ∇N · v_s.
  const double sigma = params.bound_scale;
  Vec3 dn;
  const double u = superquadric_gauge(params, sigma * q_s, &dn);
  du_dt = sigma * dn.dot(v_s);
  return u;
}

double shape_entry(GlyphShape shape, const ShapeParams& params, const Vec3& q0, const Vec3& v, double u_level,
                   double lo, double hi) {
  double t = lo;
  for (int i = 0; i < 60; ++i) {
    double slope;
    const double excess = shape_u_rate(shape, params, q0 + t * v, v, slope) - u_level;
    if (excess <= 0.0) return t;
    if (slope >= 0.0) return -1.0;
    const double next = t - excess / slope;
    if (next > hi) return -1.0;
    // Converged: the root lies within round-off of next.
    if (next - t <= 1e-13 * (std::fabs(t) + std::fabs(next)) || excess <= 1e-13 * u_level) return next;
    t = next;
  }
  return -1.0;  // not settled: no bound from this source, which is always safe
}

bool clip_to_shape_box(const ShapeParams& params, const Vec3& q0, const Vec3& v, double& t0, double& t1) {
  const double half = 1.0 / double(params.bound_scale);
  for (int k = 0; k < 3; ++k) {
    if (v[k] == 0.0) {
      if (std::fabs(q0[k]) > half) return false;
      continue;
    }
    const double a = (-half - q0[k]) / v[k], b = (half - q0[k]) / v[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  return t0 <= t1;
}

ShapeParams signed_params(const Vec3& radii, const Vec3& eigenvalues, double sharpness, SignConvention sign) {
  ShapeParams s = superquadric_params(radii, sharpness);
  const double largest = eigenvalues.cwiseAbs().maxCoeff();
  for (int k = 0; k < 3; ++k)
    if (is_compressive(eigenvalues[k], sign) && std::fabs(eigenvalues[k]) > 1e-3 * largest)
      s.pointed |= std::uint8_t(1u << k);
  if (s.pointed) s.lipschitz = float(std::sqrt(1.0 + 1.0 / (kConeBase * kConeBase)) * (1.0 + 1e-6));
  return s;
}

ShapeParams superquadric_params(const Vec3& radii, double sharpness) {
  std::array<int, 3> order{0, 1, 2};  // radii from largest to smallest
  std::sort(order.begin(), order.end(), [&](int i, int j) { return radii[i] > radii[j]; });
  ShapeParams s;
  if (!(radii.sum() > 0.0)) return s;
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
  s.bound_scale = float(superquadric_bound_scale(s.alpha, s.beta));
  return s;
}

}  // namespace hsb
