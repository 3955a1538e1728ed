#include "renderer/surface/ray_polynomial.h"

#include <cmath>

namespace hsb {
namespace {

double binomial(int n, int k) {
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * double(n - k + i) / double(i);
  return r;
}

// For every degree n ≤ 6, computed once: w, C(j, k) / C(n, k), takes power
// coefficients to Bernstein ones; v, (−1)^(k−i) C(n, k) C(k, i), back.
struct BernsteinWeights {
  double w[kMaxRayDegree + 1][kMaxRayDegree + 1][kMaxRayDegree + 1];
  double v[kMaxRayDegree + 1][kMaxRayDegree + 1][kMaxRayDegree + 1];
  BernsteinWeights() {
    for (int n = 0; n <= kMaxRayDegree; ++n)
      for (int j = 0; j <= n; ++j)
        for (int k = 0; k <= j; ++k) {
          w[n][j][k] = binomial(j, k) / binomial(n, k);
          v[n][j][k] = ((j - k) % 2 ? -1.0 : 1.0) * binomial(n, j) * binomial(j, k);
        }
  }
};
const BernsteinWeights bernstein_weights;

}  // namespace

namespace {

// The coefficients of g, g² and g³ for g(s) = q0 + q1 s + q2 s², those a
// kernel of `degree` in g needs (the quartic stops at g²: the polynomial
// sums of a ray's crowd are where its segments spend their time).
struct QuadraticPowers {
  double g[3], g2[5], g3[7];
  QuadraticPowers(double q0, double q1, double q2, int degree) : g{q0, q1, q2} {
    if (degree < 2) return;
    g2[0] = q0 * q0;
    g2[1] = 2.0 * q0 * q1;
    g2[2] = q1 * q1 + 2.0 * q0 * q2;
    g2[3] = 2.0 * q1 * q2;
    g2[4] = q2 * q2;
    if (degree < 3) return;
    g3[0] = g2[0] * q0;
    g3[1] = g2[0] * q1 + g2[1] * q0;
    g3[2] = g2[0] * q2 + g2[1] * q1 + g2[2] * q0;
    g3[3] = g2[1] * q2 + g2[2] * q1 + g2[3] * q0;
    g3[4] = g2[2] * q2 + g2[3] * q1 + g2[4] * q0;
    g3[5] = g2[3] * q2 + g2[4] * q1;
    g3[6] = g2[4] * q2;
  }
  // Adds Σ_j k_j g^j, scaled by `sign`, to `p`.
  void add(const std::array<double, 4>& k, int degree, double sign, RayPolynomial& p) const {
    p[0] += sign * k[0];
    const double k1 = sign * k[1], k2 = sign * k[2], k3 = sign * k[3];
    for (int i = 0; i < 3; ++i) p[std::size_t(i)] += k1 * g[i];
    if (degree < 2) return;
    for (int i = 0; i < 5; ++i) p[std::size_t(i)] += k2 * g2[i];
    if (degree < 3) return;
    for (int i = 0; i < 7; ++i) p[std::size_t(i)] += k3 * g3[i];
  }
};

}  // namespace

void add_kernel_along_ray(const KernelTraits& kernel, double q0, double q1, double q2, double sign,
                          RayPolynomial& p, RayPolynomial* magnitude) {
  QuadraticPowers(q0, q1, q2, kernel.degree_in_g).add(kernel.polynomial, kernel.degree_in_g, sign, p);
  if (!magnitude) return;
  const std::array<double, 4>& k = kernel.polynomial;
  const std::array<double, 4> k_abs{std::fabs(k[0]), std::fabs(k[1]), std::fabs(k[2]), std::fabs(k[3])};
  QuadraticPowers(std::fabs(q0), std::fabs(q1), std::fabs(q2), kernel.degree_in_g)
      .add(k_abs, kernel.degree_in_g, 1.0, *magnitude);
}

RayPolynomial to_bernstein(const RayPolynomial& p, int n) {
  RayPolynomial b{};
  const auto& w = bernstein_weights.w[n];
  for (int j = 0; j <= n; ++j)
    for (int k = 0; k <= j; ++k) b[std::size_t(j)] += w[j][k] * p[std::size_t(k)];
  return b;
}

RayPolynomial from_bernstein(const RayPolynomial& b, int n) {
  RayPolynomial p{};
  const auto& v = bernstein_weights.v[n];
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= k; ++i) p[std::size_t(k)] += v[k][i] * b[std::size_t(i)];
  return p;
}

void taylor_shift(RayPolynomial& p, int n, double delta) {
  for (int i = 0; i < n; ++i)
    for (int j = n - 1; j >= i; --j) p[std::size_t(j)] += delta * p[std::size_t(j + 1)];
}

}  // namespace hsb
