#pragma once
// One source's kernel along a ray as a polynomial in the ray parameter, and
// the Bernstein form that bounds and isolates roots of sums of them.
//
// Along x(t) = o + t d a source's g is the quadratic q0 + q1 s + q2 s² in
// s = t − origin, and the polynomial kernels are polynomials in g, so K(g(s))
// is a polynomial of degree at most 6 in s.

#include <array>

#include "renderer/surface/kernel.h"

namespace hsb {

constexpr int kMaxRayDegree = 6;
using RayPolynomial = std::array<double, kMaxRayDegree + 1>;  // power coefficients, lowest first

// Adds sign·P(q(s)) to `p`, P being the kernel's polynomial (kernel.h).
// When `magnitude` is given, also adds the coefficients of |P|(|q|(s)) to
// it: a bound on the size of every term this update put into `p`, from
// which the rounding of a long run of updates can be bounded.
void add_kernel_along_ray(const KernelTraits& kernel, double q0, double q1, double q2, double sign,
                          RayPolynomial& p, RayPolynomial* magnitude = nullptr);

// Power coefficients on u ∈ [0, 1] to Bernstein coefficients of degree n.
// Their convex hull holds the polynomial's graph: the largest is an upper
// bound of its values, and their sign changes bound its roots.
RayPolynomial to_bernstein(const RayPolynomial& p, int n);

// Bernstein coefficients of degree n on u ∈ [0, 1] back to power ones.
RayPolynomial from_bernstein(const RayPolynomial& b, int n);

// p(u) and p'(u) by Horner's rule, side by side.
inline double power_value(const RayPolynomial& p, int n, double u, double& slope) {
  double value = p[std::size_t(n)];
  slope = 0.0;
  for (int i = n - 1; i >= 0; --i) {
    slope = slope * u + value;
    value = value * u + p[std::size_t(i)];
  }
  return value;
}

// p(s) → p(s + delta), in place (repeated synthetic division).
void taylor_shift(RayPolynomial& p, int n, double delta);

}  // namespace hsb
