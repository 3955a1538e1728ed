// The superquadric gauge in SIMD lanes (renderer/surface/superquadric_gauge.h):
// its log₂ and exp₂ against libm's, the gauge against Kindlmann's formula
// with pow, and the same bits in every lane of every instruction set as one
// glyph alone.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "renderer/surface/superquadric_gauge.h"

namespace hsb {
namespace {

// How many units in the last place apart two doubles are.
double ulps(double a, double b) {
  if (a == b) return 0.0;
  return std::fabs(a - b) / std::fabs(std::nextafter(b, 2.0 * b + 1.0) - b);
}

TEST(SuperquadricGauge, LogAndExpAreLibmsWithinAFewUlp) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst_log = 0.0, worst_exp = 0.0;
  for (int i = 0; i < 200000; ++i) {
    // x from the gauge's least coordinate, 2⁻¹⁰⁰⁰, to far beyond any it
    // takes, dense near 1 where log₂ is small.
    const double x = i % 2 ? std::exp2(-1000.0 + 2000.0 * unit(rng)) : 1.0 + 0.01 * (unit(rng) - 0.5);
    // log₂ near 1 is near 0: its error is relative to its argument's scale.
    const double log_error = std::fabs(gauge_log2(x) - std::log2(x)) /
                             std::max(std::fabs(std::log2(x)), std::fabs(x - 1.0) + 1e-300);
    worst_log = std::max(worst_log, log_error / 0x1p-52);
    const double y = -64.0 * unit(rng);
    worst_exp = std::max(worst_exp, ulps(gauge_exp2(y), std::exp2(y)));
  }
  EXPECT_LT(worst_log, 4.0);
  EXPECT_LT(worst_exp, 4.0);
  // Exact where the gauge relies on it: a power of 0 is 1, log₂ 1 is 0.
  EXPECT_EQ(gauge_exp2(0.0), 1.0);
  EXPECT_EQ(gauge_exp2(-64.0), 0x1p-64);
  EXPECT_EQ(gauge_log2(1.0), 0.0);
  EXPECT_EQ(gauge_log2(0x1p-64), -64.0);
  EXPECT_EQ(gauge_log2(2.0), 1.0);
  EXPECT_EQ(gauge_log2(0x1p-1000), -1000.0);
  EXPECT_EQ(gauge_log2(0x1p900), 900.0);
}

struct Glyph {
  double qa, qb, qz, alpha, beta;
};

Glyph random_glyph(std::mt19937& rng) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> exponent(0.0, 1.0);
  Glyph g{n(rng), n(rng), n(rng), exponent(rng), exponent(rng)};
  // Some sharp (exponents near 0, powers in the thousands), some points on
  // an axis or a plane, where a term is exactly 0.
  if (rng() % 5 == 0) g.alpha = 1e-3 * exponent(rng);
  if (rng() % 7 == 0) g.qb = 0.0;
  if (rng() % 11 == 0) g.qa = g.qb = 0.0;
  return g;
}

void set_lane(GaugeLanes& lanes, int i, const Glyph& g) {
  lanes.qa[i] = g.qa, lanes.qb[i] = g.qb, lanes.qz[i] = g.qz;
  lanes.alpha[i] = g.alpha, lanes.beta[i] = g.beta;
}

TEST(SuperquadricGauge, IsKindlmannsSuperquadricNorm) {
  std::mt19937 rng(5);
  for (int i = 0; i < 20000; ++i) {
    const Glyph g = random_glyph(rng);
    if (g.alpha < 0.05 || g.beta < 0.05) continue;  // pow's terms overflow there; the lanes divide first
    GaugeLanes lanes;
    set_lane(lanes, 0, g);
    superquadric_gauges(lanes, 1);
    const double p = 2.0 / g.alpha, r = 2.0 / g.beta;
    const double equator = std::pow(std::pow(std::fabs(g.qa), p) + std::pow(std::fabs(g.qb), p), 1.0 / p);
    const double n = std::pow(std::pow(equator, r) + std::pow(std::fabs(g.qz), r), 1.0 / r);
    ASSERT_NEAR(lanes.n[0], n, 1e-13 * n) << "α " << g.alpha << " β " << g.beta;
    // ∇N by central differences.
    const auto gauge_at = [&](double a, double b, double z) {
      GaugeLanes one;
      set_lane(one, 0, {a, b, z, g.alpha, g.beta});
      superquadric_gauges(one, 1);
      return one.n[0];
    };
    const double h = 1e-6;
    EXPECT_NEAR(lanes.da[0], (gauge_at(g.qa + h, g.qb, g.qz) - gauge_at(g.qa - h, g.qb, g.qz)) / (2 * h), 1e-5);
    EXPECT_NEAR(lanes.dz[0], (gauge_at(g.qa, g.qb, g.qz + h) - gauge_at(g.qa, g.qb, g.qz - h)) / (2 * h), 1e-5);
  }
}

TEST(SuperquadricGauge, EveryLaneOfEveryInstructionSetGivesOneGlyphsBits) {
  std::mt19937 rng(7);
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  int compared = 0;
  for (const InstructionSet isa : supported_isas())
    for (int batch = 0; batch < 500; ++batch) {
      const int count = 2 + int(rng() % (kGaugeLanes - 1));  // every batch width: 2, 4 and kGaugeLanes
      GaugeLanes lanes;
      Glyph glyphs[kGaugeLanes];
      for (int i = 0; i < count; ++i) set_lane(lanes, i, glyphs[i] = random_glyph(rng));
      superquadric_gauges(lanes, count, isa);
      for (int i = 0; i < count; ++i) {
        GaugeLanes one;
        set_lane(one, 0, glyphs[i]);
        superquadric_gauges(one, 1, isa);
        ASSERT_TRUE(same(lanes.n[i], one.n[0]) && same(lanes.da[i], one.da[0]) && same(lanes.db[i], one.db[0]) &&
                    same(lanes.dz[i], one.dz[0]))
            << isa_name(isa) << " lane " << i << " of " << count << ": " << lanes.n[i] << " against " << one.n[0];
        ++compared;
      }
    }
  EXPECT_GT(compared, 1000);
}

}  // namespace
}  // namespace hsb
