// The shape tracer's bounds of many spans at once (renderer/surface/span_bounds.h):
// the SIMD loops give the bits of each span alone's bound, summed in the
// documented order, for every kernel, every run of spans and every kind of
// span (never evaluated, with a falling or a rising tangent, begun after
// t, ended before it), under the instruction set in force (run again under
// each by the isa.* tests); a bound never falls as the interval grows, and
// a span that ended before t adds nothing.

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "renderer/surface/instruction_set.h"
#include "renderer/surface/span_bounds.h"

namespace hsb {
namespace {

// Spans as a walk standing at t = 1 holds them: in the order they begin,
// some begun before t (live, or ended before it), the rest after; a fifth
// never evaluated, the others with a tangent before t, falling or rising.
struct Columns {
  std::vector<double> t0, t1, t_c, a, g_min, fall, u, du_dt, tangent_at;
  SpanColumns view() const {
    return {t0.data(), t1.data(), t_c.data(), a.data(), g_min.data(), fall.data(),
            u.data(), du_dt.data(), tangent_at.data()};
  }
};

Columns random_spans(int count, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Columns c;
  double begins = 0.0;
  for (int k = 0; k < count; ++k) {
    begins += 0.04 * unit(rng);  // sorted by where they begin; about half before t = 1
    const double t0 = begins, t1 = t0 + 3.0 * unit(rng) * unit(rng);
    c.t0.push_back(t0);
    c.t1.push_back(t1);
    c.t_c.push_back(t0 + (t1 - t0) * (1.5 * unit(rng) - 0.25));
    c.a.push_back(5.0 * unit(rng));
    c.g_min.push_back(1.2 * unit(rng));
    c.fall.push_back(3.0 * unit(rng));
    const bool evaluated = unit(rng) > 0.2;
    c.tangent_at.push_back(evaluated ? t0 + (1.0 - t0) * unit(rng) : -std::numeric_limits<double>::infinity());
    c.u.push_back(1.5 * unit(rng));
    c.du_dt.push_back(unit(rng) < 0.5 ? -2.0 * unit(rng) : 2.0 * unit(rng));
  }
  return c;
}

TEST(SpanBounds, LanesGiveTheBitsOfEachSpanAloneInTheDocumentedOrder) {
  std::mt19937 rng(17);
  const Columns spans = random_spans(203, rng);  // not a multiple of any vector width
  const SpanColumns c = spans.view();
  const double t = 1.0;
  int nonzero = 0, ended = 0;
  std::vector<double> each(spans.t0.size());
  for (const KernelKind kernel : {KernelKind::wyvill, KernelKind::quartic, KernelKind::blinn}) {
    // Each span's bound where the walk stands.
    for (const std::size_t first : {std::size_t{0}, std::size_t{3}, std::size_t{61}}) {
      span_bounds_at(c, first, spans.t0.size(), t, kernel, each.data());
      for (std::size_t i = first; i < spans.t0.size(); ++i) {
        const double alone = span_bound(c, i, t, t, kernel);
        ASSERT_EQ(std::memcmp(&each[i - first], &alone, sizeof alone), 0)
            << isa_name(active_isa()) << " span " << i << " from " << first;
      }
    }
    for (const double s : {1.0, 1.5, 2.7, 9.0})
      // Every run the proofs ask for: fewer spans than one group, whole
      // groups, groups with a rest, from the start and from further on.
      for (const std::size_t first : {std::size_t{0}, std::size_t{3}})
        for (const std::size_t end : {std::size_t{3}, std::size_t{8}, std::size_t{13}, std::size_t{67},
                                      std::size_t{200}, spans.t0.size()}) {
          // Span k places past `first` into running sum k mod 8, the sums
          // added pairwise.
          double sums[kSumLanes] = {};
          for (std::size_t i = first; i < end; ++i) {
            const double alone = span_bound(c, i, t, s, kernel);
            sums[(i - first) % kSumLanes] += alone;
            ASSERT_GE(span_bound(c, i, t, s + 1.0, kernel), alone) << "span " << i;
            if (spans.t1[i] < t) {
              ASSERT_EQ(alone, 0.0) << "span " << i << " ended before t";
              ++ended;
            }
            nonzero += alone > 0.0;
          }
          const double expected =
              ((sums[0] + sums[1]) + (sums[2] + sums[3])) + ((sums[4] + sums[5]) + (sums[6] + sums[7]));
          const double got = span_bounds_sum(c, first, end, t, s, kernel);
          ASSERT_EQ(std::memcmp(&expected, &got, sizeof got), 0)
              << isa_name(active_isa()) << " spans [" << first << ", " << end << ") s " << s << ": " << got
              << " against " << expected;
        }
  }
  EXPECT_GT(nonzero, 3000);
  EXPECT_GT(ended, 100);
}

// What a bound is made of: a span never evaluated falls from u = 1 at its
// edge at its greatest rate; with a falling tangent, the tangent's line;
// with a rising one, its value where the interval starts; and the bounding
// ellipsoid's g_e where that is larger.
TEST(SpanBounds, EachKindOfSpanIsBoundedByWhatIsKnownOfIt) {
  const double inf = std::numeric_limits<double>::infinity();
  // t0 t1 t_c a g_min fall u du tangent_at
  Columns c;
  const auto add = [&](double t0, double tangent_at, double u, double du) {
    c.t0.push_back(t0), c.t1.push_back(10.0), c.t_c.push_back(5.0), c.a.push_back(1e-6), c.g_min.push_back(0.0);
    c.fall.push_back(0.25), c.u.push_back(u), c.du_dt.push_back(du), c.tangent_at.push_back(tangent_at);
  };
  add(0.0, -inf, 0.0, 0.0);  // never evaluated: u ≥ 1 − 0.25 (s − 0)
  add(0.0, 0.5, 0.9, -0.1);  // falling tangent at 0.5: u ≥ 0.9 − 0.1 (s − 0.5)
  add(0.0, 0.5, 0.6, 0.1);   // rising tangent at 0.5: u ≥ 0.6 + 0.1 (t − 0.5) from t on
  add(3.0, -inf, 0.0, 0.0);  // begins after t: u ≥ 1 − 0.25 (s − 3)
  const SpanColumns v = c.view();
  const double t = 1.0, s = 2.0;
  EXPECT_DOUBLE_EQ(span_bound_g(v, 0, t, s), 0.5 * 0.5);
  EXPECT_DOUBLE_EQ(span_bound_g(v, 1, t, s), 0.75 * 0.75);
  EXPECT_DOUBLE_EQ(span_bound_g(v, 2, t, s), 0.65 * 0.65);
  EXPECT_DOUBLE_EQ(span_bound_g(v, 3, t, 4.0), 0.75 * 0.75);
  // Past its reach the tangent's line would go below zero: u ≥ 0, and the
  // bounding ellipsoid takes over where it is the larger.
  c.a[1] = 1.0;  // g_e = (min(t_near, to) − 5)², t_near = 5
  EXPECT_DOUBLE_EQ(span_bound_g(c.view(), 1, t, 20.0), 0.0);  // the line below 0, g_e 0 at t_c
  EXPECT_DOUBLE_EQ(span_bound_g(c.view(), 1, t, 4.0), 1.0);   // g_e 1, above the line's 0.55²
}

}  // namespace
}  // namespace hsb
