// Colour-bar ticks: round values and tidy labels for any range a data set
// can produce, including ones that are constant up to round-off.

#include <gtest/gtest.h>

#include <cfloat>
#include <chrono>
#include <cmath>

#include "renderer/image/ticks.h"

namespace hsb {
namespace {

void expect_inside_and_increasing(const TickSet& set, double lo, double hi) {
  for (std::size_t i = 0; i < set.ticks.size(); ++i) {
    EXPECT_GE(set.ticks[i].value, lo - 1e-9 * std::fabs(lo)) << i;
    EXPECT_LE(set.ticks[i].value, hi + 1e-9 * std::fabs(hi)) << i;
    EXPECT_FALSE(set.ticks[i].label.empty());
    if (i > 0) {
      EXPECT_GT(set.ticks[i].value, set.ticks[i - 1].value);
    }
  }
}

TEST(Ticks, OrdinaryRangesGetRoundStepsAndPlainLabels) {
  const TickSet a = linear_ticks(-4.0, 0.0);
  ASSERT_GE(a.ticks.size(), 3u);
  EXPECT_EQ(a.ticks.front().label, "\u22124");
  EXPECT_EQ(a.ticks.back().label, "0");
  EXPECT_TRUE(a.factor.empty());
  const TickSet b = linear_ticks(-780.0, 760.0);
  expect_inside_and_increasing(b, -780.0, 760.0);
  EXPECT_GE(b.ticks.size(), 3u);
  const TickSet c = linear_ticks(2e6, 9e6);
  EXPECT_EQ(c.factor, "\u00d710\u2076");
  expect_inside_and_increasing(c, 2e6, 9e6);
}

// A bar centred on zero with sides of different sizes: each half its own
// round steps, zero once, one factor for both.
TEST(Ticks, TwoSidedRangesGetEachHalfsOwnSteps) {
  const TickSet disc = two_sided_ticks(-968.0, 24.5);
  expect_inside_and_increasing(disc, -968.0, 24.5);
  int zeros = 0, above = 0, below = 0;
  for (const Tick& t : disc.ticks) zeros += t.value == 0.0, above += t.value > 0.0, below += t.value < 0.0;
  EXPECT_EQ(zeros, 1);
  EXPECT_GE(above, 2);  // 10, 20: linear ticks over [−968, 24.5] had none above zero
  EXPECT_GE(below, 2);
  EXPECT_TRUE(disc.factor.empty());
  const TickSet huge = two_sided_ticks(-5e7, 1.6e9);
  expect_inside_and_increasing(huge, -5e7, 1.6e9);
  EXPECT_EQ(huge.factor, "\u00d710\u2079");  // the larger side's
  EXPECT_EQ(huge.ticks.front().value, -4e7);
  EXPECT_EQ(huge.ticks.front().label, "\u22120.04");
  // A range on one side of zero is an ordinary one.
  EXPECT_EQ(two_sided_ticks(2.0, 9.0).ticks.size(), linear_ticks(2.0, 9.0).ticks.size());
}

// Ranges that are one value up to round-off once looped for ever (a tick
// step below the values' resolution), at any magnitude.
TEST(Ticks, RangesConstantUpToRoundOffGiveOneTickAtOnce) {
  const auto start = std::chrono::steady_clock::now();
  for (const double v : {1.0, -1.0, 3e-300, 1e300, 123.456, -7e-12}) {
    for (const double ulps : {1.0, 2.0, 1000.0}) {
      const double lo = v, hi = v + ulps * std::fabs(v) * DBL_EPSILON;
      if (!(hi > lo)) continue;
      const TickSet set = linear_ticks(lo, hi);
      ASSERT_EQ(set.ticks.size(), 1u) << v << " + " << ulps << " ulps";
      expect_inside_and_increasing(set, lo, hi);
    }
  }
  EXPECT_EQ(linear_ticks(1.0, 1.0).ticks.size(), 0u);  // not a range
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

TEST(Ticks, HugeAndTinyRangesStayFewAndFinite) {
  for (const auto& [lo, hi] : {std::pair{-DBL_MAX, DBL_MAX}, std::pair{0.0, DBL_MAX}, std::pair{-1e-300, 1e-300},
                               std::pair{0.0, DBL_TRUE_MIN * 1e10}, std::pair{1e15, 1e15 + 64.0}}) {
    const TickSet set = linear_ticks(lo, hi);
    EXPECT_GE(set.ticks.size(), 1u) << lo << " " << hi;
    EXPECT_LE(set.ticks.size(), 22u) << lo << " " << hi;
    for (const Tick& t : set.ticks) EXPECT_TRUE(std::isfinite(t.value));
    expect_inside_and_increasing(set, lo, hi);
  }
  EXPECT_TRUE(linear_ticks(0.0, INFINITY).ticks.empty());
  EXPECT_TRUE(linear_ticks(NAN, 1.0).ticks.empty());
}

TEST(Ticks, LogBarsOverManyDecadesLabelAFewPowers) {
  const TickSet fine = log_ticks(1.0, 50.0);
  EXPECT_EQ(fine.ticks.size(), 6u);  // 1 2 5 10 20 50
  for (const auto& [lo, hi] : {std::pair{1e-300, 1e300}, std::pair{DBL_TRUE_MIN, DBL_MAX}, std::pair{1e-3, 1e9}}) {
    const TickSet set = log_ticks(lo, hi);
    EXPECT_GE(set.ticks.size(), 2u) << lo << " " << hi;
    EXPECT_LE(set.ticks.size(), 10u) << lo << " " << hi;
    expect_inside_and_increasing(set, lo, hi);
  }
  EXPECT_TRUE(log_ticks(0.0, 1.0).ticks.empty());
  EXPECT_TRUE(log_ticks(1.0, INFINITY).ticks.empty());
}

}  // namespace
}  // namespace hsb
