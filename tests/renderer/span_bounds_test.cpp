// The shape tracer's bounds of many spans at once (renderer/surface/span_bounds.h):
// the SIMD rows sum to the bits of each span alone's bound added in the
// documented order, for every kernel and every count of rows, under the
// instruction set in force (run again under each by the isa.* tests), and
// a bound never falls as the interval grows.

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "renderer/surface/instruction_set.h"
#include "renderer/surface/span_bounds.h"

namespace hsb {
namespace {

TEST(SpanBounds, RowsInLanesSumToTheBitsOfEachSpanAlone) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  SpanBoundRows rows;
  std::vector<SpanBoundRow> pushed;
  for (int k = 0; k < 203; ++k) {  // not a multiple of any vector width, and past two growths
    // Bounds from `from` ≤ 0.5, the smallest s asked.
    const double t_c = 4.0 * unit(rng), from = 0.5 * unit(rng);
    // Half the rows with a floor of u (a signed glyph's points), half with none.
    pushed.push_back({from + 4.0 * unit(rng), 1.5 * unit(rng), unit(rng) < 0.2 ? 0.0 : -3.0 * unit(rng),
                      4.0 * unit(rng), std::max(t_c, from), t_c, 5.0 * unit(rng), 1.2 * unit(rng),
                      k % 2 ? 0.0 : 1.1 * unit(rng)});
    rows.push(pushed.back());
  }
  // Each row reads back as it was written, the columns kept apart.
  ASSERT_EQ(rows.size(), pushed.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const SpanBoundRow a = rows.row(k), b = pushed[k];
    ASSERT_TRUE(a.t1 == b.t1 && a.u0 == b.u0 && a.rate == b.rate && a.tau == b.tau && a.t_near == b.t_near &&
                a.t_c == b.t_c && a.a == b.a && a.g_min == b.g_min && a.u_floor == b.u_floor)
        << "row " << k;
  }
  int nonzero = 0;
  for (const KernelKind kernel : {KernelKind::wyvill, KernelKind::quartic, KernelKind::blinn})
    for (const double s : {0.5, 2.0, 3.7, 9.0})
      // Every prefix the proofs ask for: fewer rows than one group, whole
      // groups, and groups with a rest.
      for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{4},
                                      std::size_t{5}, std::size_t{8}, std::size_t{64}, std::size_t{197}, rows.size()}) {
        // Row k into running sum k mod 8, the sums added pairwise.
        double sums[kSumLanes] = {};
        for (std::size_t k = 0; k < count; ++k) {
          const double alone = span_bound(rows.row(k), s, kernel);
          sums[k % kSumLanes] += alone;
          ASSERT_GE(span_bound(rows.row(k), s + 1.0, kernel), alone);
          nonzero += alone > 0.0;
        }
        const double expected =
            ((sums[0] + sums[1]) + (sums[2] + sums[3])) + ((sums[4] + sums[5]) + (sums[6] + sums[7]));
        const double got = span_bounds_sum(rows, count, s, kernel);
        ASSERT_EQ(std::memcmp(&expected, &got, sizeof got), 0)
            << isa_name(active_isa()) << " rows " << count << " s " << s << ": " << got << " against " << expected;
      }
  EXPECT_GT(nonzero, 300);
}

}  // namespace
}  // namespace hsb
