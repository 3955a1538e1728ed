#include "renderer/surface/superquadric_gauge.h"

#include "base/bit_cast.h"
#include "renderer/surface/isa_variants.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace hsb {

namespace {

// log₂ x for x in [2⁻⁶⁴, 2] (normal, positive). x = 2^e m with m in
// [√½, √2), e read from the bits (biased by 1024 so that the shift is a
// logical one, which every set has for 64-bit lanes); ln m = 2 artanh s
// with s = (m − 1)/(m + 1), |s| ≤ 0.172, by its series to s²³ (the next
// term is below 10⁻¹⁸ of the sum). log₂ 1 is exactly 0.
[[gnu::always_inline]] inline double log2_core(double x) {
  constexpr std::uint64_t kSqrtHalf = 0x3FE6A09E667F3BCDull;
  const std::uint64_t bits = bit_cast<std::uint64_t>(x);
  const std::uint64_t biased = (bits - kSqrtHalf + (std::uint64_t(1024) << 52)) >> 52;
  const double m = bit_cast<double>(bits - ((biased - 1024) << 52));
  // 2⁵² + biased, exactly, less 2⁵²: the exponent as a double without an
  // integer conversion (which takes AVX-512 for 64-bit lanes).
  const double e = (bit_cast<double>(0x4330000000000000ull | biased) - 0x1p52) - 1024.0;
  const double s = (m - 1.0) / (m + 1.0), z = s * s;
  // Σ z^j/(2j + 1), j ≤ 11, by Estrin's scheme: pairs, then pairs of pairs,
  // a third of Horner's chain of dependent steps (a glyph alone, as Newton
  // and the shading ask, waits for every one of them).
  const double z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;
  const double p01 = 1.0 + z * (1.0 / 3), p23 = 1.0 / 5 + z * (1.0 / 7), p45 = 1.0 / 9 + z * (1.0 / 11);
  const double p67 = 1.0 / 13 + z * (1.0 / 15), p89 = 1.0 / 17 + z * (1.0 / 19), p1011 = 1.0 / 21 + z * (1.0 / 23);
  const double p = ((p01 + z2 * p23) + z4 * (p45 + z2 * p67)) + z8 * (p89 + z2 * p1011);
  return e + (2.0 * s * p) * 1.4426950408889634;  // ln m · log₂ e
}

// 2^y for y in [−64, 0]: 2^k 2^f with k the nearest integer (added to
// 1.5·2⁵², its bits hold k) and f in [−½, ½], 2^f = e^{f ln 2} by its
// Taylor series to degree 13 (the next term is below 10⁻¹⁷ of it), 2^k
// from the bits. 2⁰ is exactly 1.
[[gnu::always_inline]] inline double exp2_core(double y) {
  constexpr double kRound = 0x1.8p52;
  const double shifted = y + kRound;
  const double k = shifted - kRound;
  const double f = (y - k) * 0.6931471805599453;  // f ln 2
  // e^f = Σ f^n/n!, n ≤ 13, by Estrin's scheme as above (every n! here
  // is exact).
  const double f2 = f * f, f4 = f2 * f2, f8 = f4 * f4;
  const double p01 = 1.0 + f, p23 = 1.0 / 2 + f * (1.0 / 6), p45 = 1.0 / 24 + f * (1.0 / 120);
  const double p67 = 1.0 / 720 + f * (1.0 / 5040), p89 = 1.0 / 40320 + f * (1.0 / 362880);
  const double p1011 = 1.0 / 3628800 + f * (1.0 / 39916800), p1213 = 1.0 / 479001600 + f * (1.0 / 6227020800);
  const double p = ((p01 + f2 * p23) + f4 * (p45 + f2 * p67)) + f8 * ((p89 + f2 * p1011) + f4 * p1213);
  return p * bit_cast<double>((bit_cast<std::uint64_t>(shifted) + 1023) << 52);
}

// ‖(x, y)‖_p for p ≥ 2 and its partial derivatives, each in [−1, 1]. The
// terms are divided by the larger one first: |x|^p for p = 2·10⁶ would
// overflow or vanish, (|x|/m)^p is 1 for the larger term and harmless for
// the other. Each power comes with its derivative's, without dividing:
//   r^{p−1} = ∂‖·‖/∂(smaller) / (∂‖·‖/∂(larger)),
//   ‖·‖ = m · S^{1/p} and ∂‖·‖/∂(larger) = S^{1/p − 1}, S = 1 + r^p.
// r^{p−1} below 2⁻⁶⁴ is 0: such a term leaves S = 1 unchanged, and its part
// of the gradient is below the larger's last bit. Branch-free, so a loop of
// it runs in SIMD lanes.
[[gnu::always_inline]] inline void p_norm_core(double x, double y, double p, double inv_p, double& value, double& dx,
                                               double& dy) {
  const double ax = std::fabs(x), ay = std::fabs(y);
  const bool x_large = ax >= ay;
  const double m = x_large ? ax : ay, small = x_large ? ay : ax;
  const bool any = m > 0.0;
  const double r = small / (any ? m : 1.0);
  const double power = (p - 1.0) * log2_core(std::max(r, 0x1p-64));
  const double slope_ratio = power > -64.0 ? exp2_core(std::max(power, -64.0)) : 0.0;
  const double sum = 1.0 + slope_ratio * r;  // in [1, 2]
  const double d_large = exp2_core((inv_p - 1.0) * log2_core(sum));
  const double d_small = slope_ratio * d_large;
  value = m * (d_large * sum);
  dx = any ? std::copysign(x_large ? d_large : d_small, x) : 0.0;
  dy = any ? std::copysign(x_large ? d_small : d_large, y) : 0.0;
}

[[gnu::always_inline]] inline void gauge_lane(GaugeLanes& l, int i) {
  double e, de_da, de_db, n, dn_de, dn_dz;
  p_norm_core(l.qa[i], l.qb[i], 2.0 / l.alpha[i], 0.5 * l.alpha[i], e, de_da, de_db);
  p_norm_core(e, l.qz[i], 2.0 / l.beta[i], 0.5 * l.beta[i], n, dn_de, dn_dz);
  l.n[i] = n;
  l.da[i] = dn_de * de_da;
  l.db[i] = dn_de * de_db;
  l.dz[i] = dn_dz;
}

// Every lane, a fixed count: the loop becomes whole vectors. One variant
// per instruction set (isa_variants.h).
#define HSB_GAUGE_KERNEL(suffix, target_isa)                                               \
  __attribute__((target(target_isa))) void gauges_##suffix(GaugeLanes& __restrict lanes) { \
    for (int i = 0; i < kGaugeLanes; ++i) gauge_lane(lanes, i);                             \
  }

HSB_FOR_EACH_ISA(HSB_GAUGE_KERNEL)
#undef HSB_GAUGE_KERNEL

// In InstructionSet order.
constexpr void (*kGauges[])(GaugeLanes&) = {gauges_sse2, gauges_sse42, gauges_avx, gauges_avx2, gauges_avx512};

}  // namespace

void superquadric_gauges(GaugeLanes& lanes, int count, InstructionSet isa) {
  // One glyph alone (Newton's entry, the shading): the same arithmetic on
  // one lane, without filling the rest.
  if (count <= 1) {
    if (count == 1) gauge_lane(lanes, 0);
    return;
  }
  // The idle lanes repeat the first glyph: finite, and discarded.
  for (int i = count; i < kGaugeLanes; ++i) {
    lanes.qa[i] = lanes.qa[0], lanes.qb[i] = lanes.qb[0], lanes.qz[i] = lanes.qz[0];
    lanes.alpha[i] = lanes.alpha[0], lanes.beta[i] = lanes.beta[0];
  }
  kGauges[std::size_t(isa)](lanes);
}

void superquadric_gauges(GaugeLanes& lanes, int count) { superquadric_gauges(lanes, count, active_isa()); }

double gauge_log2(double x) { return log2_core(x); }
double gauge_exp2(double y) { return exp2_core(y); }

}  // namespace hsb
