#pragma once
// Metaball influence kernels K(u), u ∈ [0, 1], zero outside (paper eq. 9, 10).
//
// Every kernel here is written as a function of g = u², the squared
// anisotropic distance of eq. 11, because g is what a ray gives cheaply
// (a quadratic in t) and the polynomial kernels are polynomials in g.

#include <cmath>

namespace hsb {

enum class KernelKind {
  wyvill,   // eq. 10: a u⁶ + b u⁴ + c u² + 1; K(½) = ½
  quartic,  // (1 − u²)²: POV-Ray's blob density
  blinn,    // eq. 9 made compact, see blinn_sharpness below; K(½) = ½
};

// Blinn's exponential exp(−s u²) shifted and rescaled so that it is 1 at
// u = 0 and exactly 0 at u = 1 (compact support, like the others):
//   K(u) = (exp(−s u²) − exp(−s)) / (1 − exp(−s)).
// s is chosen so that K(½) = ½, as for `wyvill`: an isolated source at the
// default isovalue ½ is then the same ellipsoid under both kernels.
inline constexpr double blinn_sharpness = 2.4375114537440252;

namespace detail {
inline constexpr double wyvill_a = -4.0 / 9.0;
inline constexpr double wyvill_b = 17.0 / 9.0;
inline constexpr double wyvill_c = -22.0 / 9.0;
inline const double blinn_floor = std::exp(-blinn_sharpness);
inline const double blinn_norm = 1.0 / (1.0 - blinn_floor);
}  // namespace detail

// K as a function of g = u².
inline double kernel_value(KernelKind kind, double g) {
  if (g >= 1.0) return 0.0;
  switch (kind) {
    case KernelKind::wyvill:
      return ((detail::wyvill_a * g + detail::wyvill_b) * g + detail::wyvill_c) * g + 1.0;
    case KernelKind::quartic:
      return (1.0 - g) * (1.0 - g);
    case KernelKind::blinn:
      return (std::exp(-blinn_sharpness * g) - detail::blinn_floor) * detail::blinn_norm;
  }
  return 0.0;
}

// dK/dg, for the analytic gradient ∇F = Σ dK/dg · 2M(x − c).
inline double kernel_slope(KernelKind kind, double g) {
  if (g >= 1.0) return 0.0;
  switch (kind) {
    case KernelKind::wyvill:
      return (3.0 * detail::wyvill_a * g + 2.0 * detail::wyvill_b) * g + detail::wyvill_c;
    case KernelKind::quartic:
      return -2.0 * (1.0 - g);
    case KernelKind::blinn:
      return -blinn_sharpness * std::exp(-blinn_sharpness * g) * detail::blinn_norm;
  }
  return 0.0;
}

// max over u ∈ [0, 1] of |dK/du|. Along a ray u(t) = |M^½(p + t d)| changes
// at most at rate √(dᵀMd), so this times √(dᵀMd) bounds the slope of one
// source's contribution (the directional step bound of design §5).
// tests/renderer/kernel_test.cpp checks these against dense sampling.
inline double kernel_max_du_slope(KernelKind kind) {
  switch (kind) {
    case KernelKind::wyvill:
      return 1.5834297477401706;  // at u ≈ 0.50347, where d²K/du² = 0
    case KernelKind::quartic:
      return 1.5396007178390020;  // 8 / (3√3), at u = 1/√3
    case KernelKind::blinn:
      return 1.4674055850147556;  // √(2s)·e^(−½)/(1 − e^(−s)), at u = 1/√(2s)
  }
  return 0.0;
}

// The u at which an isolated source's kernel equals the isovalue C, i.e. the
// fraction of R·r_k that an isolated glyph's semi-axes measure.
double kernel_level_radius(KernelKind kind, double isovalue);

const char* kernel_name(KernelKind kind);

}  // namespace hsb
