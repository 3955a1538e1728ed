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

// Σ_j k_j g^j for g(s) = q0 + q1 s + q2 s², the powers a kernel of
// `degree` in g needs, times `sign`, added to `p`. Every coefficient is a
// scalar of its own and `p` is updated in one pass over all seven, the
// same loads and stores every call: kept in small arrays, the powers and
// the sum went through the stack and were read back in 16-byte pieces of
// 8-byte stores (store-forwarding stalls, most of this function's time
// over a ray's crowd of sources).
void add_powers(const std::array<double, 4>& k, int degree, double q0, double q1, double q2, double sign,
                RayPolynomial& p) {
  double t0 = k[0] + k[1] * q0, t1 = k[1] * q1, t2 = k[1] * q2, t3 = 0.0, t4 = 0.0, t5 = 0.0, t6 = 0.0;
  if (degree >= 2) {
    const double a0 = q0 * q0, a1 = 2.0 * q0 * q1, a2 = q1 * q1 + 2.0 * q0 * q2, a3 = 2.0 * q1 * q2, a4 = q2 * q2;
    t0 += k[2] * a0, t1 += k[2] * a1, t2 += k[2] * a2, t3 += k[2] * a3, t4 += k[2] * a4;
    if (degree >= 3) {
      t0 += k[3] * (a0 * q0);
      t1 += k[3] * (a0 * q1 + a1 * q0);
      t2 += k[3] * (a0 * q2 + a1 * q1 + a2 * q0);
      t3 += k[3] * (a1 * q2 + a2 * q1 + a3 * q0);
      t4 += k[3] * (a2 * q2 + a3 * q1 + a4 * q0);
      t5 += k[3] * (a3 * q2 + a4 * q1);
      t6 += k[3] * (a4 * q2);
    }
  }
  p[0] += sign * t0, p[1] += sign * t1, p[2] += sign * t2, p[3] += sign * t3;
  p[4] += sign * t4, p[5] += sign * t5, p[6] += sign * t6;
}

}  // namespace

void add_kernel_along_ray(const KernelTraits& kernel, double q0, double q1, double q2, double sign,
                          RayPolynomial& p, RayPolynomial* magnitude) {
  add_powers(kernel.polynomial, kernel.degree_in_g, q0, q1, q2, sign, p);
  if (!magnitude) return;
  const std::array<double, 4>& k = kernel.polynomial;
  const std::array<double, 4> k_abs{std::fabs(k[0]), std::fabs(k[1]), std::fabs(k[2]), std::fabs(k[3])};
  add_powers(k_abs, kernel.degree_in_g, std::fabs(q0), std::fabs(q1), std::fabs(q2), 1.0, *magnitude);
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
