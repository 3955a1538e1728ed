// The walk over support intervals and the running upper bound of F: each
// against a brute-force answer on random rays' worth of spans.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "renderer/surface/event_queue.h"
#include "renderer/surface/field_bound.h"
#include "renderer/surface/support_sweep.h"

namespace hsb {
namespace {

// A span of the quadratic g(t) = a (t − t_c)² + g_min, clipped to [lo, hi].
RaySpan span_of(double a, double t_c, double g_min, double lo, double hi, std::uint32_t source) {
  const double half = std::sqrt((1.0 - g_min) / a);
  return {std::max(lo, t_c - half), std::min(hi, t_c + half), a, t_c, g_min, source};
}

// Random spans on [0, 10]: wide and narrow supports (sizes over three orders
// of magnitude), some clipped at the ends, where they share an endpoint.
std::vector<RaySpan> random_spans(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<RaySpan> spans;
  for (int i = 0; spans.size() < std::size_t(n); ++i) {
    const double width = std::pow(10.0, -2.0 + 3.0 * u(rng));  // 0.01 … 10
    const double g_min = 0.95 * u(rng);
    const double a = (1.0 - g_min) / (0.25 * width * width);
    const RaySpan s = span_of(a, -1.0 + 12.0 * u(rng), g_min, 0.0, 10.0, std::uint32_t(i));
    if (s.t0 < s.t1) spans.push_back(s);
  }
  return spans;
}

TEST(RayEventQueue, GivesEventsInSortedOrder) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 5.0);
  for (const int n : {0, 1, 2, 17, 1000}) {
    std::vector<RayEvent> events;
    for (int i = 0; i < n; ++i) events.push_back({i % 5 == 0 ? 2.5 : u(rng), std::uint32_t(i)});  // ties too
    std::vector<RayEvent> expected = events;
    std::sort(expected.begin(), expected.end());
    RayEventQueue queue;
    queue.assign(events, 0.0);
    std::vector<RayEvent> got;
    for (RayEvent e; queue.peek(e); queue.pop()) got.push_back(e);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_EQ(got[k].t, expected[k].t);
      EXPECT_EQ(got[k].index, expected[k].index);
    }
  }
}

TEST(SupportSweep, SegmentsAndActiveSetsMatchBruteForce) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<RaySpan> spans = random_spans(rng, 1 + trial % 60);
    const double tmin = trial % 3 == 0 ? 1.5 : 0.0, tmax = trial % 5 == 0 ? 7.0 : 10.0;
    SupportSweep sweep;
    sweep.begin(spans, tmin, tmax);
    std::set<std::uint32_t> tracked;  // what entered() and left() said
    double start, end, previous_end = tmin;
    while (sweep.next(
        tmax, start, end, [&](std::uint32_t i) { EXPECT_TRUE(tracked.insert(i).second); },
        [&](std::uint32_t i) { EXPECT_EQ(tracked.erase(i), 1u); })) {
      ASSERT_LT(start, end);
      ASSERT_GE(start, previous_end);
      ASSERT_LE(end, tmax);
      // No endpoint falls strictly inside the segment, and F is zero in
      // any gap skipped before it.
      for (const RaySpan& s : spans) {
        EXPECT_FALSE(s.t0 > start && s.t0 < end) << "an entry inside [" << start << ", " << end << "]";
        EXPECT_FALSE(s.t1 > start && s.t1 < end) << "an exit inside [" << start << ", " << end << "]";
        const double mid = 0.5 * (previous_end + start);
        if (start > previous_end) {
          EXPECT_FALSE(s.t0 < mid && mid < s.t1) << "skipped a covered gap";
        }
      }
      // The active set is exactly the spans covering the segment.
      const double mid = 0.5 * (start + end);
      std::set<std::uint32_t> expected;
      for (std::uint32_t i = 0; i < spans.size(); ++i)
        if (spans[i].t0 <= start && spans[i].t1 >= end && spans[i].t0 < mid && mid < spans[i].t1) expected.insert(i);
      const std::set<std::uint32_t> active(sweep.active().begin(), sweep.active().end());
      EXPECT_EQ(active, expected);
      EXPECT_EQ(tracked, expected);
      previous_end = end;
    }
    // Nothing covered is left unvisited.
    for (const RaySpan& s : spans)
      if (s.t0 < tmax && s.t1 > tmin) {
        EXPECT_LE(std::min(s.t1, tmax), previous_end) << "a span was never walked";
      }
  }
}

double kernel_sum(KernelKind kind, const std::vector<RaySpan>& spans, double t) {
  double f = 0.0;
  for (const RaySpan& s : spans)
    if (s.t0 <= t && t <= s.t1) f += kernel_value(kind, s.g(t));
  return f;
}

// The largest F on [lo, hi] by dense sampling (a lower estimate of the max).
double sampled_max(KernelKind kind, const std::vector<RaySpan>& spans, double lo, double hi) {
  double best = 0.0;
  for (int k = 0; k <= 400; ++k) best = std::max(best, kernel_sum(kind, spans, lo + (hi - lo) * k / 400.0));
  return best;
}

// Walks the spans with the bound, proving what it can at many levels; a
// proof where the sampled field reaches the level is a failure.
void expect_bounds_are_sound(KernelKind kind, unsigned seed) {
  std::mt19937 rng(seed);
  int proofs = 0, rest_proofs = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const std::vector<RaySpan> spans = random_spans(rng, 5 + trial % 120);
    std::vector<double> peaks;
    for (const RaySpan& s : spans) peaks.push_back(kernel_value(kind, s.g(std::clamp(s.t_c, s.t0, s.t1))));
    const double level = 0.25 + 0.1 * (trial % 8);
    SupportSweep sweep;
    FieldUpperBound bound;
    sweep.begin(spans, 0.0, 10.0);
    bound.reset(kernel_traits(kind), spans, peaks, 0.0, false);
    double start, end;
    while (sweep.next(
        10.0, start, end, [&](std::uint32_t i) { bound.add(spans[i]); },
        [&](std::uint32_t i) { bound.remove(spans[i]); })) {
      if (bound.proves_rest_below(level, start, spans, sweep.active())) {
        ++rest_proofs;
        EXPECT_LT(sampled_max(kind, spans, start, 10.0), level) << "rest proven below where F reaches the level";
      }
      if (bound.proves_below(level, start, end, spans, sweep.active())) {
        ++proofs;
        EXPECT_LT(sampled_max(kind, spans, start, end), level) << "segment proven below where F reaches the level";
      }
    }
  }
  // And the bounds do prove things: they are not vacuously safe.
  EXPECT_GT(proofs, 1000);
  EXPECT_GT(rest_proofs, 10);
}

TEST(FieldUpperBound, NeverProvesBelowWhereTheFieldReachesTheLevel) {
  expect_bounds_are_sound(KernelKind::wyvill, 3);
  expect_bounds_are_sound(KernelKind::quartic, 4);
}

TEST(FieldUpperBound, BlinnsPolynomialLiesAboveItsKernel) {
  // kernel.cpp's claim, at a million points of g ∈ [0, 1].
  const KernelTraits& blinn = kernel_traits(KernelKind::blinn);
  ASSERT_FALSE(blinn.exact);
  double closest = 1.0;
  for (int i = 0; i <= 1000000; ++i) {
    const double g = i / 1e6;
    double p = 0.0;
    for (int j = 3; j >= 0; --j) p = p * g + blinn.polynomial[std::size_t(j)];
    closest = std::min(closest, p - kernel_value(KernelKind::blinn, g));
  }
  EXPECT_GT(closest, 0.0);
  EXPECT_LT(closest, 1e-4);  // and it is tight
}

TEST(FieldUpperBound, RoundingOfLongRunsIsCountedAgainstTheProof) {
  // A thousand narrow sources pass while one wide one stays: the running
  // sum's cancellation grows, and the bound must still never prove a
  // segment below where the wide source alone reaches the level.
  std::vector<RaySpan> spans;
  spans.push_back(span_of(4.0 / 100.0, 5.0, 0.0, 0.0, 10.0, 0));  // wide: support [0, 10]
  for (int i = 0; i < 1000; ++i) spans.push_back(span_of(4.0 / 1e-6, 0.01 * i + 0.003, 0.5, 0.0, 10.0, std::uint32_t(i + 1)));
  std::vector<double> peaks;
  for (const RaySpan& s : spans) peaks.push_back(kernel_value(KernelKind::wyvill, s.g(std::clamp(s.t_c, s.t0, s.t1))));
  const double level = kernel_value(KernelKind::wyvill, spans[0].g(5.0)) - 1e-9;  // reached only near t = 5
  SupportSweep sweep;
  FieldUpperBound bound;
  sweep.begin(spans, 0.0, 10.0);
  bound.reset(kernel_traits(KernelKind::wyvill), spans, peaks, 0.0, false);
  double start, end;
  bool walked_past_peak = false;
  while (sweep.next(
      10.0, start, end, [&](std::uint32_t i) { bound.add(spans[i]); },
      [&](std::uint32_t i) { bound.remove(spans[i]); })) {
    if (start <= 5.0 && 5.0 <= end) {
      walked_past_peak = true;
      EXPECT_FALSE(bound.proves_below(level, start, end, spans, sweep.active()));
    } else {
      bound.proves_below(level, start, end, spans, sweep.active());
    }
  }
  EXPECT_TRUE(walked_past_peak);
}

}  // namespace
}  // namespace hsb
