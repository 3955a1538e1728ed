#include "renderer/surface/superquadric_gauge.h"

#include "base/bit_cast.h"
#include "renderer/surface/isa_variants.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace hsb {

namespace {

// log₂ x for a positive normal x (the gauge takes |q| ≥ 2⁻¹⁰⁰⁰). x = 2^e m
// with m in [√½, √2), e read from the bits (biased by 1024 so that the
// shift is a logical one, which every set has for 64-bit lanes); ln m =
// 2 artanh s with s = (m − 1)/(m + 1), |s| ≤ 0.172, by its series to s²³
// (the next term is below 10⁻¹⁸ of the sum). log₂ 1 is exactly 0.
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

// Coordinates below this are 0 to the gauge: their log₂ stays finite.
constexpr double kTiny = 0x1p-1000;

// ‖(x, y)‖_p for p ≥ 2 from |x|, |y| and their log₂ (lx, ly), in log space:
// the ratio r of the smaller to the larger is 2^(ls − lm), so its powers
// need no division and no log₂ of their own, and the norm's own log₂, lm +
// log₂(S)/p with S = 1 + r^p, is what the next norm of the gauge takes. So
// a glyph's gauge waits on three log₂ and three exp₂ one after another
// (log₂ |q|, r^p, log₂ S, twice, then S^{1/p}) where dividing for r and
// taking log₂ of each norm's value made it eight and two divisions: an
// 8-lane batch 133 -> 108 ns. Out: the norm, its log₂, and its partial
// derivatives by the larger and the smaller coordinate, each in [0, 1]:
//   ∂‖·‖/∂(larger) = S^{1/p − 1},  ∂‖·‖/∂(smaller) = r^{p−1} S^{1/p − 1}.
// A power r^k below 2⁻⁶⁴ is 0: such a term leaves S = 1 unchanged, and its
// part of the gradient is below the larger's last bit. Branch-free, so a
// loop of it runs in SIMD lanes.
struct PNorm {
  double value, log_value, d_larger, d_smaller;
  bool x_larger;
};
[[gnu::always_inline]] inline PNorm p_norm_core(double ax, double ay, double lx, double ly, double p,
                                                double inv_p) {
  PNorm out;
  out.x_larger = lx >= ly;
  const double m = out.x_larger ? ax : ay;
  const double lm = out.x_larger ? lx : ly, lr = (out.x_larger ? ly : lx) - lm;  // log₂ r ≤ 0
  const double slope_power = (p - 1.0) * lr, power = p * lr;
  const double slope_ratio = slope_power > -64.0 ? exp2_core(std::max(slope_power, -64.0)) : 0.0;
  const double sum = 1.0 + (power > -64.0 ? exp2_core(std::max(power, -64.0)) : 0.0);  // in [1, 2]
  const double log_sum = log2_core(sum);
  out.d_larger = exp2_core((inv_p - 1.0) * log_sum);
  out.d_smaller = slope_ratio * out.d_larger;
  out.value = m * (out.d_larger * sum);
  out.log_value = lm + inv_p * log_sum;
  return out;
}

[[gnu::always_inline]] inline void gauge_lane(GaugeLanes& l, int i) {
  const double qa = l.qa[i], qb = l.qb[i], qz = l.qz[i];
  const double aa = std::fabs(qa), ab = std::fabs(qb), az = std::fabs(qz);
  const double la = log2_core(std::max(aa, kTiny)), lb = log2_core(std::max(ab, kTiny));
  const double lz = log2_core(std::max(az, kTiny));
  // The equator's norm E = ‖(q_a, q_b)‖_{2/α}, then N = ‖(E, q_z)‖_{2/β}.
  const PNorm e = p_norm_core(aa, ab, la, lb, 2.0 / l.alpha[i], 0.5 * l.alpha[i]);
  const PNorm n = p_norm_core(e.value, az, e.log_value, lz, 2.0 / l.beta[i], 0.5 * l.beta[i]);
  // A norm of 0 (every coordinate 0 to the gauge) has no direction: ∇ = 0.
  const bool any_e = e.value > 0.0, any_n = n.value > 0.0;
  const double de_da = any_e ? std::copysign(e.x_larger ? e.d_larger : e.d_smaller, qa) : 0.0;
  const double de_db = any_e ? std::copysign(e.x_larger ? e.d_smaller : e.d_larger, qb) : 0.0;
  const double dn_de = any_n ? (n.x_larger ? n.d_larger : n.d_smaller) : 0.0;
  l.n[i] = n.value;
  l.da[i] = dn_de * de_da;
  l.db[i] = dn_de * de_db;
  l.dz[i] = any_n ? std::copysign(n.x_larger ? n.d_smaller : n.d_larger, qz) : 0.0;
}

// Every lane of a batch kLanes wide, a fixed count: the loop becomes whole
// vectors. One variant per instruction set (isa_variants.h), and per width.
#define HSB_GAUGE_KERNEL(suffix, target_isa)                                                                  \
  template <int kLanes>                                                                                      \
  __attribute__((target(target_isa))) void gauges_##suffix(GaugeLanes& __restrict lanes) {                   \
    for (int i = 0; i < kLanes; ++i) gauge_lane(lanes, i);                                                    \
  }

HSB_FOR_EACH_ISA(HSB_GAUGE_KERNEL)
#undef HSB_GAUGE_KERNEL

// A probe mostly asks for two or three glyphs (on fig17's beads as
// superquadrics, 70 % of the batches hold two): the narrowest batch that
// holds them costs the least, as the wider vectors take more of the core
// (on a Xeon with AVX-512, a chain of calls: 8 lanes 359 ns whatever they
// held, 4 lanes 247 ns, 2 lanes 201 ns, one glyph alone 190 ns).
constexpr int kWidths[] = {2, 4, kGaugeLanes};
using GaugeKernel = void (*)(GaugeLanes&);
#define HSB_GAUGE_WIDTHS(suffix) {gauges_##suffix<2>, gauges_##suffix<4>, gauges_##suffix<kGaugeLanes>}
// In InstructionSet order, then width.
constexpr GaugeKernel kGauges[][3] = {HSB_GAUGE_WIDTHS(sse2), HSB_GAUGE_WIDTHS(sse42), HSB_GAUGE_WIDTHS(avx),
                                      HSB_GAUGE_WIDTHS(avx2), HSB_GAUGE_WIDTHS(avx512)};
#undef HSB_GAUGE_WIDTHS

}  // namespace

void superquadric_gauges(GaugeLanes& lanes, int count, InstructionSet isa) {
  // One glyph alone (Newton's entry, the shading): the same arithmetic on
  // one lane, without filling the rest.
  if (count <= 1) {
    if (count == 1) gauge_lane(lanes, 0);
    return;
  }
  std::size_t width = 0;
  while (kWidths[width] < count) ++width;
  // The idle lanes repeat the first glyph: finite, and discarded.
  for (int i = count; i < kWidths[width]; ++i) {
    lanes.qa[i] = lanes.qa[0], lanes.qb[i] = lanes.qb[0], lanes.qz[i] = lanes.qz[0];
    lanes.alpha[i] = lanes.alpha[0], lanes.beta[i] = lanes.beta[0];
  }
  kGauges[std::size_t(isa)][width](lanes);
}

void superquadric_gauges(GaugeLanes& lanes, int count) { superquadric_gauges(lanes, count, active_isa()); }

double gauge_log2(double x) { return log2_core(x); }
double gauge_exp2(double y) { return exp2_core(y); }

}  // namespace hsb
