#pragma once
// Metaball influence kernels K(u), u ∈ [0, 1], zero outside (paper eq. 9, 10).
//
// Every kernel here is written as a function of g = u², the squared
// anisotropic distance of eq. 11, because g is what a ray gives cheaply
// (a quadratic in t) and the polynomial kernels are polynomials in g.

#include <array>
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

// What the scene reader, the intersectors and the exporters know about a
// kernel, in one table (kernel.cpp).
struct KernelTraits {
  KernelKind kind;
  const char* name;
  // max over u ∈ [0, 1] of |dK/du|. Along a ray u(t) = |M^½(p + t d)|
  // changes at most at rate √(dᵀMd), so this times √(dᵀMd) bounds the slope
  // of one source's contribution (the directional step bound of design §5).
  // tests/renderer/kernel_test.cpp checks it against dense sampling.
  double max_du_slope;
  // Power coefficients in g of a polynomial P(g) of degree `degree_in_g`
  // with P ≥ K on g ∈ [0, 1]. Where `exact` P is K itself (wyvill, quartic),
  // so the field along a ray is a polynomial between support endpoints;
  // otherwise (blinn) P is a close upper bound, still good for proving
  // that F stays below C.
  int degree_in_g;
  std::array<double, 4> polynomial;
  bool exact;
};

const KernelTraits& kernel_traits(KernelKind kind);
// Every kernel, in the order the scene reference lists them.
const std::array<KernelTraits, 3>& all_kernel_traits();

inline const char* kernel_name(KernelKind kind) { return kernel_traits(kind).name; }
inline double kernel_max_du_slope(KernelKind kind) { return kernel_traits(kind).max_du_slope; }

// The u at which an isolated source's kernel equals the isovalue C, i.e. the
// fraction of R·r_k that an isolated glyph's semi-axes measure.
double kernel_level_radius(KernelKind kind, double isovalue);

}  // namespace hsb
