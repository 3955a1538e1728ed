// Every instruction set the renderer can trace with: the switch that picks
// one, and the span kernels compiled for each, held to the same bits.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "renderer/surface/instruction_set.h"
#include "renderer/surface/ray_span.h"

namespace hsb {
namespace {

TEST(InstructionSet, NamesRoundTripAndUnknownOnesAreRefused) {
  for (InstructionSet isa : {InstructionSet::sse2, InstructionSet::sse42, InstructionSet::avx, InstructionSet::avx2,
                             InstructionSet::avx512})
    EXPECT_EQ(parse_isa(isa_name(isa)), isa);
  EXPECT_EQ(parse_isa("sse4.2"), InstructionSet::sse42);
  EXPECT_FALSE(parse_isa("avx3"));
  EXPECT_FALSE(parse_isa("AVX2"));
  EXPECT_FALSE(parse_isa(""));
}

TEST(InstructionSet, TheProcessorsSetsAreALadderFromSse2) {
  // Every x86-64 processor has SSE2, and each set includes the ones below.
  const std::vector<InstructionSet> isas = supported_isas();
  ASSERT_FALSE(isas.empty());
  EXPECT_EQ(isas.front(), InstructionSet::sse2);
  for (std::size_t i = 0; i < isas.size(); ++i) EXPECT_EQ(int(isas[i]), int(i));
  EXPECT_EQ(best_supported_isa(), isas.back());
  // Whatever the suite was started with (HSB_ISA) is one of them.
  EXPECT_TRUE(processor_supports(active_isa()));
}

void expect_same_bits(double x, double y, const char* what, InstructionSet isa, int lane) {
  EXPECT_EQ(std::memcmp(&x, &y, sizeof x), 0) << what << " differs on " << isa_name(isa) << " lane " << lane << ": " << x
                                              << " against " << y;
}

// Every field a lane of `spans` fills against the span ray_span() made alone.
void expect_same_span(const SpanLanes& spans, int i, const RaySpan& alone, InstructionSet isa) {
  expect_same_bits(spans.t0[i], alone.t0, "t0", isa, i);
  expect_same_bits(spans.t1[i], alone.t1, "t1", isa, i);
  expect_same_bits(spans.a[i], alone.a, "a", isa, i);
  expect_same_bits(spans.t_c[i], alone.t_c, "t_c", isa, i);
  expect_same_bits(spans.g_min[i], alone.g_min, "g_min", isa, i);
  expect_same_bits(spans.lower_a[i], alone.lower_a, "lower_a", isa, i);
  expect_same_bits(spans.lower_t[i], alone.lower_t, "lower_t", isa, i);
  expect_same_bits(spans.lower_g[i], alone.lower_g, "lower_g", isa, i);
}

// Sources of every shape and distance, rays from near and far: each
// variant's lanes must equal the scalar ray_span() bit for bit, so a ray's
// spans never depend on the processor or on how it was packed.
TEST(SpanKernels, EveryInstructionSetGivesTheScalarBits) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::normal_distribution<double> normal;
  int entered = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    const Vec3 radii(std::pow(10.0, unit(rng)), std::pow(10.0, unit(rng) - 1.0), 0.05);
    const BlobSource source =
        make_blob_source(Vec3(unit(rng), unit(rng), unit(rng)), q.normalized().toRotationMatrix(), radii, 1.3, {1, 1, 1});
    RayLanes rays;
    const double distance = std::pow(10.0, 3.0 * (unit(rng) + 1.0));  // 1 to 10⁶ away
    for (int i = 0; i < kMaxPacket; ++i) {
      const Vec3 o = distance * Vec3(normal(rng), normal(rng), normal(rng)).normalized();
      const Vec3 d = (0.5 * Vec3(unit(rng), unit(rng), unit(rng)) - o).normalized();
      rays.set(i, o, d, i % 3 == 0 ? 0.0 : distance * 0.9, i % 4 == 0 ? INFINITY : distance * 1.1);
    }
    const int first = trial % 2 ? 0 : 8, count = trial % 2 ? kMaxPacket : 8;
    // Without a box, with one and a cylinder about each axis that cut the
    // ellipsoid's support, and with those and the double cones of a signed
    // glyph's points, on every set of axes (none: a superquadric's support
    // through the pointed kernel).
    ShapeSupport support;
    if (trial % 3 == 0) support = {1.0 / 1.5, (1.0 + 0.4 * unit(rng)) / 1.5, trial / 3 % 3};
    if (trial % 3 == 1) support = {1.0 / 1.5, (1.0 + 0.4 * unit(rng)) / 1.5, trial / 3 % 3, unsigned(trial / 3 % 8)};
    const auto ray_kernel = [&](const SpanKernels& kernels) {
      if (trial % 3 == 1) return kernels.ray_spans_pointed;
      return support.bounded() ? kernels.ray_spans_boxed : kernels.ray_spans;
    };
    for (InstructionSet isa : supported_isas()) {
      SpanLanes spans;
      const SpanKernels& kernels = span_kernels(isa);
      const unsigned mask = ray_kernel(kernels)(source, support, rays, first, count, spans);
      for (int i = first; i < first + count; ++i) {
        RaySpan alone;
        const bool enters = ray_span(source, 7, 0, Vec3(rays.ox[i], rays.oy[i], rays.oz[i]),
                                     Vec3(rays.dx[i], rays.dy[i], rays.dz[i]), rays.tmin[i], rays.tmax[i], alone,
                                     support);
        ASSERT_EQ(bool(mask & (1u << i)), enters) << isa_name(isa) << " lane " << i;
        if (!enters) continue;
        ++entered;
        expect_same_span(spans, i, alone, isa);
      }
      EXPECT_EQ(mask & ~(((1u << count) - 1u) << first), 0u) << "lanes outside the asked ones";
    }

    // One ray against sixteen sources, the other way round.
    SourceLanes lanes;
    std::vector<BlobSource> listed;
    for (int k = 0; k < kMaxPacket - trial % 5; ++k) {
      const BlobSource s = make_blob_source(Vec3(unit(rng), unit(rng), unit(rng)), Mat3::Identity(),
                                            Vec3(0.3, 0.2, 0.1) * (1.0 + unit(rng)), 1.3, {1, 1, 1});
      for (int r = 0; r < 9; ++r) lanes.w[r][k] = s.w[std::size_t(r)];
      for (int c = 0; c < 3; ++c) lanes.c[c][k] = s.centre[std::size_t(c)];
      lanes.index[k] = std::uint32_t(k);
      listed.push_back(s);
    }
    lanes.count = int(listed.size());
    lanes.boxed = support.bounded();
    lanes.pointed = trial % 3 == 1 ? 7u : 0u;
    std::vector<ShapeSupport> supports;  // each source's own axis, radius and points
    for (int k = 0; k < kMaxPacket; ++k) {
      supports.push_back(support.bounded() ? ShapeSupport{support.box, support.radius * (1.0 + 0.1 * unit(rng)), k % 3,
                                                          lanes.pointed ? unsigned(k % 8) : 0u}
                                           : support);
      lanes.set_support(k, supports.back());
    }
    for (int k = lanes.count; k < kMaxPacket; ++k) {  // unused lanes: a source no ray meets
      for (int r = 0; r < 9; ++r) lanes.w[r][k] = 0.0;
      for (int c = 0; c < 3; ++c) lanes.c[c][k] = 0.0;
    }
    const Vec3 o(rays.ox[0], rays.oy[0], rays.oz[0]), d = (Vec3(unit(rng), unit(rng), unit(rng)) * 0.3 - o).normalized();
    for (InstructionSet isa : supported_isas()) {
      SpanLanes spans;
      const SpanKernels& kernels = span_kernels(isa);
      const unsigned mask = (lanes.pointed ? kernels.source_spans_pointed
                                           : (lanes.boxed ? kernels.source_spans_boxed : kernels.source_spans))(
          lanes, o, d, 0.0, INFINITY, spans);
      for (int k = 0; k < lanes.count; ++k) {
        RaySpan alone;
        const bool enters =
            ray_span(listed[std::size_t(k)], 0, 0, o, d, 0.0, INFINITY, alone, supports[std::size_t(k)]);
        ASSERT_EQ(bool(mask & (1u << k)), enters) << isa_name(isa) << " source " << k;
        if (!enters) continue;
        ++entered;
        expect_same_span(spans, k, alone, isa);
      }
    }
  }
  EXPECT_GT(entered, 2000);  // the rays did meet the sources
}

// A span narrowed to its source's box and cylinder holds exactly the ray's
// points inside the ellipsoid's support, the box and the cylinder: its
// ends are on their surfaces, and points of the ellipsoid's span beyond
// them are outside one of them. Rays parallel to the box's faces (the
// sources' axes along the world's) are inside a slab everywhere or
// nowhere, and those along the cylinder's axis inside it everywhere or
// nowhere.
TEST(SpanKernels, ABoxAndACylinderNarrowTheSpanToBoth) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::normal_distribution<double> normal;
  const double box = 1.0 / std::sqrt(3.0);  // the corners of the box touch the ellipsoid
  int narrowed = 0, dropped = 0, by_cylinder = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const bool aligned = trial % 4 == 0;
    // Between the square's inscribed and circumscribed circles: the
    // cylinder cuts the box's edges along its axis.
    const ShapeSupport support{box, box * (1.2 + 0.2 * unit(rng)), trial / 8 % 3};
    const Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    const Mat3 axes = aligned ? Mat3::Identity() : Mat3(q.normalized().toRotationMatrix());
    const BlobSource source = make_blob_source(Vec3::Zero(), axes, Vec3(0.5, 0.3, 0.2), 1.0, {1, 1, 1});
    const Vec3 o = 3.0 * Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    Vec3 d = (0.4 * Vec3(unit(rng), unit(rng), unit(rng)) - o).normalized();
    if (aligned) d = Vec3(0.0, 0.0, 0.0), d[trial % 3] = o[trial % 3] > 0.0 ? -1.0 : 1.0;  // along a world axis
    RaySpan plain, narrow, boxed;
    if (!ray_span(source, 0, 0, o, d, 0.0, 10.0, plain)) continue;
    const Mat3 w = shape_matrix(source);
    const auto inside = [&](double t, double slack) {
      Vec3 q_s = w * (o + t * d);
      const bool in_box = q_s.cwiseAbs().maxCoeff() <= box * (1.0 + slack);
      q_s[support.axis] = 0.0;
      return in_box && q_s.norm() <= support.radius * (1.0 + slack);
    };
    const bool in_box = ray_span(source, 0, 0, o, d, 0.0, 10.0, boxed, ShapeSupport{box, kNoBox, support.axis});
    if (!ray_span(source, 0, 0, o, d, 0.0, 10.0, narrow, support)) {
      // Nowhere inside both: no sample of the ellipsoid's span is.
      ++dropped;
      by_cylinder += in_box;
      for (int k = 0; k <= 64; ++k) EXPECT_FALSE(inside(plain.t0 + (plain.t1 - plain.t0) * k / 64.0, -1e-9));
      continue;
    }
    ++narrowed;
    by_cylinder += narrow.t0 > boxed.t0 || narrow.t1 < boxed.t1;
    EXPECT_GE(narrow.t0, plain.t0);
    EXPECT_LE(narrow.t1, plain.t1);
    EXPECT_TRUE(inside(narrow.t0, 1e-9) && inside(narrow.t1, 1e-9)) << "trial " << trial;
    for (int k = 1; k < 64; ++k) {
      const double before = plain.t0 + (narrow.t0 - plain.t0) * k / 64.0;
      const double after = narrow.t1 + (plain.t1 - narrow.t1) * k / 64.0;
      EXPECT_FALSE(narrow.t0 > plain.t0 && inside(before, -1e-9)) << "trial " << trial;
      EXPECT_FALSE(narrow.t1 < plain.t1 && inside(after, -1e-9)) << "trial " << trial;
    }
  }
  EXPECT_GT(narrowed, 500);
  EXPECT_GT(dropped, 50);
  EXPECT_GT(by_cylinder, 200);  // the cylinder cut what the box alone let through
}

}  // namespace
}  // namespace hsb
