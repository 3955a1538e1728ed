// A ray's answer must not depend on the order its spans were collected in:
// Embree's BVH traversal order changes with the instruction set (BVH4 or
// BVH8, packet width), and the pictures are the same bytes on every one.

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "renderer/surface/field_ray.h"

namespace hsb {
namespace {

TEST(SpanOrder, FirstCrossingAndSurfaceAreTheSameBitsInAnyOrder) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const KernelKind kernel : {KernelKind::wyvill, KernelKind::quartic, KernelKind::blinn}) {
    // A dense crowd with exact ties: every source twice over in mirror
    // image pairs, so equal entries and equal peaks occur.
    BlobField field;
    field.kernel = kernel;
    for (int i = 0; i < 60; ++i) {
      const Vec3 c(0.4 * unit(rng), 0.4 * unit(rng), 0.4 * unit(rng));
      const Vec3 radii(0.2, 0.1 + 0.05 * unit(rng), 0.08);
      const Mat3 axes = Eigen::AngleAxisd(unit(rng), Vec3(unit(rng), unit(rng), 1.0).normalized()).toRotationMatrix();
      field.sources.push_back(make_blob_source(c, axes, radii, 1.3, {float(unit(rng) + 1), 0.5f, 0.2f}, c.x()));
      field.sources.push_back(make_blob_source(Vec3(-c.x(), c.y(), c.z()), axes, radii, 1.3, {0.2f, 0.5f, 0.9f}));
    }
    std::vector<std::uint32_t> rank(field.sources.size());
    std::iota(rank.begin(), rank.end(), 0u);
    std::shuffle(rank.begin(), rank.end(), rng);

    int hits = 0;
    for (int r = 0; r < 600; ++r) {
      // Half the rays start inside the crowd, as a ray's later query
      // windows do: every support around the start is clipped there, so
      // entries tie at t = 0.
      const bool inside = r % 2 == 0;
      const Vec3 o = inside ? Vec3(0.5 * unit(rng), 0.5 * unit(rng), 0.5 * unit(rng))
                            : Vec3(2.0 * Vec3(unit(rng), unit(rng), unit(rng)).normalized());
      const Vec3 d = inside ? Vec3(Vec3(unit(rng), unit(rng), unit(rng)).normalized())
                            : Vec3((Vec3(0.0, 0.3 * unit(rng), 0.3 * unit(rng)) - o).normalized());
      std::vector<RaySpan> spans;
      for (std::uint32_t i = 0; i < field.sources.size(); ++i) {
        RaySpan span;
        if (ray_span(field.sources[i], i, rank[i], o, d, 0.0, 4.0, span)) spans.push_back(span);
      }
      for (const Intersector method : {Intersector::exact, Intersector::sphere}) {
        if (method == Intersector::exact && !exact_crossing_supported(kernel, field.blend)) continue;
        TraceSettings settings;
        settings.intersector = method;
        FieldRay reference;
        TraceStats stats;
        reference.spans = spans;
        const double t = reference.first_crossing(field, o, d, 0.0, 4.0, settings, stats);
        const SurfaceSample expected = t >= 0.0 ? reference.surface_at(field, o, d, t) : SurfaceSample{};
        hits += t >= 0.0;
        for (int shuffle = 0; shuffle < 4; ++shuffle) {
          FieldRay other;
          other.spans = spans;
          std::shuffle(other.spans.begin(), other.spans.end(), rng);
          ASSERT_EQ(other.first_crossing(field, o, d, 0.0, 4.0, settings, stats), t) << "ray " << r;
          FieldRay shadow;
          shadow.spans = other.spans;
          EXPECT_EQ(shadow.first_crossing(field, o, d, 0.0, 4.0, settings, stats, CrossingQuery::any) >= 0.0, t >= 0.0);
          if (t < 0.0) continue;
          const SurfaceSample got = other.surface_at(field, o, d, t);
          EXPECT_EQ(got.normal, expected.normal) << "ray " << r;
          EXPECT_EQ(got.color, expected.color) << "ray " << r;
          EXPECT_EQ(got.scalar, expected.scalar) << "ray " << r;
          EXPECT_EQ(got.source, expected.source) << "ray " << r;
          EXPECT_EQ(got.crowd, expected.crowd) << "ray " << r;
        }
      }
    }
    EXPECT_GT(hits, 400) << "kernel " << int(kernel);
  }
}

}  // namespace
}  // namespace hsb
