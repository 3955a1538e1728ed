// Rays traced against a list of the sources around them (nearby_sources.h,
// ambient_rays.h) against the same rays traced through the span BVH: the
// same spans, in the same order, so the same answers to the bit.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include "renderer/render/ambient_rays.h"
#include "renderer/render/ray_scene.h"
#include "renderer/surface/nearby_sources.h"
#include "renderer/surface/single_source.h"
#include "renderer/surface/spatial_rank.h"
#include "tests/renderer/span_sources.h"

namespace hsb {
namespace {

// A dense crowd of randomly turned, flattened sources whose supports
// overlap many times over, as on fig06's cap.
BlobField crowd(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  BlobField field;
  for (int i = 0; i < n; ++i) {
    const Vec3 centre(unit(rng) - 0.5, unit(rng) - 0.5, 0.3 * (unit(rng) - 0.5));
    const Mat3 axes =
        Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
    const Vec3 radii(0.15 + 0.1 * unit(rng), 0.1 + 0.1 * unit(rng), 0.04 + 0.04 * unit(rng));
    field.sources.push_back(make_blob_source(centre, axes, radii, 1.0, {0.5f, 0.5f, 0.5f}));
  }
  field.isovalue = 0.5;
  return field;
}

Vec3 random_direction(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  return Vec3(normal(rng), normal(rng), normal(rng)).normalized();
}

TEST(NearbySources, SpansAreEachSourcesOwnInListOrder) {
  const BlobField field = crowd(50, 1);
  NearbySources list;
  for (std::uint32_t i = 0; i < field.sources.size(); ++i) list.add(field, i, i, influence_bounds(field, i));
  ASSERT_EQ(list.size(), field.sources.size());
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  int entered = 0;
  for (int r = 0; r < 200; ++r) {
    const Vec3 o(unit(rng), unit(rng), unit(rng)), d = random_direction(rng);
    std::vector<RaySpan> listed;
    list.collect_spans(o, d, 0.0, 0.7, listed);
    std::vector<RaySpan> one_by_one;
    for (std::uint32_t i = 0; i < field.sources.size(); ++i) {
      RaySpan span;
      if (ray_span(field.sources[i], i, i, o, d, 0.0, 0.7, span)) one_by_one.push_back(span);
    }
    ASSERT_EQ(listed.size(), one_by_one.size());
    for (std::size_t k = 0; k < listed.size(); ++k) {
      // Bit for bit: the SIMD lanes and the scalar path round alike.
      EXPECT_EQ(listed[k].source, one_by_one[k].source);
      EXPECT_EQ(listed[k].rank, one_by_one[k].rank);
      EXPECT_EQ(listed[k].t0, one_by_one[k].t0);
      EXPECT_EQ(listed[k].t1, one_by_one[k].t1);
      EXPECT_EQ(listed[k].a, one_by_one[k].a);
      EXPECT_EQ(listed[k].t_c, one_by_one[k].t_c);
      EXPECT_EQ(listed[k].g_min, one_by_one[k].g_min);
    }
    entered += int(listed.size());
  }
  EXPECT_GT(entered, 200);  // the rays do cross the crowd
}

TEST(SpatialRank, IsAPermutationThatKeepsNeighboursClose) {
  const BlobField field = crowd(400, 3);
  const std::vector<std::uint32_t> rank = spatial_ranks(field, influence_bounds(field));
  std::set<std::uint32_t> seen(rank.begin(), rank.end());
  ASSERT_EQ(seen.size(), field.sources.size());
  EXPECT_EQ(*seen.rbegin(), field.sources.size() - 1);
  // Consecutive ranks are much closer together than random pairs.
  std::vector<std::uint32_t> by_rank(rank.size());
  for (std::uint32_t i = 0; i < rank.size(); ++i) by_rank[rank[i]] = i;
  auto centre = [&](std::uint32_t i) {
    const auto& c = field.sources[i].centre;
    return Vec3(c[0], c[1], c[2]);
  };
  double consecutive = 0.0, shuffled = 0.0;
  for (std::size_t r = 1; r < by_rank.size(); ++r) {
    consecutive += (centre(by_rank[r]) - centre(by_rank[r - 1])).norm();
    shuffled += (centre(std::uint32_t(r)) - centre(std::uint32_t(r - 1))).norm();
  }
  EXPECT_LT(consecutive, 0.5 * shuffled);
}

class CrowdScene : public ::testing::Test {
 protected:
  const EmbreeDevice device;
  const BlobField field = crowd(300, 4);
  const RayScene scene{device, field, TraceSettings{Intersector::exact}};
  const BlobGeometry& blobs = scene.blobs();
};

TEST_F(CrowdScene, GatherListsExactlyTheSourcesWhoseBoxesMeetTheRegion) {
  const Box3 region{Vec3(-0.1, -0.05, -0.1), Vec3(0.15, 0.1, 0.05)};
  NearbySources list;
  std::vector<std::uint32_t> scratch;
  ASSERT_TRUE(blobs.gather_nearby(region, field.sources.size(), list, scratch));
  std::set<std::uint32_t> expected;
  for (std::uint32_t i = 0; i < field.sources.size(); ++i)
    if (influence_bounds(field, i).overlaps(region)) expected.insert(i);
  EXPECT_EQ(std::set<std::uint32_t>(scratch.begin(), scratch.end()), expected);
  EXPECT_EQ(list.size(), expected.size());
  EXPECT_GT(expected.size(), 50u);
  EXPECT_LT(expected.size(), field.sources.size());
  // Past the limit it gives up.
  EXPECT_FALSE(blobs.gather_nearby(region, expected.size() - 1, list, scratch));
}

TEST_F(CrowdScene, ListedAndTraversedRaysAgreeToTheBit) {
  const Box3 region{Vec3(-0.6, -0.6, -0.6), Vec3(0.6, 0.6, 0.6)};
  NearbySources list;
  std::vector<std::uint32_t> scratch;
  ASSERT_TRUE(blobs.gather_nearby(region, field.sources.size(), list, scratch));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-0.3, 0.3);
  FieldRay listed, traversed;
  TraceStats stats;
  int hits = 0, misses = 0, pruned = 0;
  for (int r = 0; r < 400; ++r) {
    const RayInterval ray{Vec3(unit(rng), unit(rng), 0.2 + 0.1 * unit(rng)), random_direction(rng), 0.0, 0.3};
    for (const CrossingQuery query : {CrossingQuery::first, CrossingQuery::any}) {
      const double a = blobs.first_crossing_near(list, ray, listed, stats, query);
      const double b = blobs.first_crossing_traversed(ray, traversed, stats, query);
      (a >= 0.0 ? hits : misses) += 1;
      if (query == CrossingQuery::any) {
        // Some point at or above C, each the first it met: the same verdict.
        ASSERT_EQ(a >= 0.0, b >= 0.0) << "ray " << r;
        continue;
      }
      ASSERT_EQ(a, b) << "ray " << r;
      // The same spans (in different orders: list rank, BVH traversal):
      // the traversal stops where the ray enters a source's own level
      // surface, and the crossing keeps only the sources that begin
      // before that entry, from either.
      ASSERT_EQ(span_sources(listed), span_sources(traversed)) << "ray " << r;
      // Fewer sources reach the traversal than the list holds.
      std::vector<RaySpan> all;
      list.collect_spans(ray.origin, ray.direction, ray.tmin, ray.tmax, all);
      FieldRay gathered;
      blobs.collect_spans(&ray, 1, &gathered);
      ASSERT_LE(gathered.spans.size(), all.size()) << "ray " << r;
      pruned += gathered.spans.size() < all.size();
      if (a >= 0.0) {
        const SurfaceSample x = listed.surface_at(field, ray.origin, ray.direction, a);
        const SurfaceSample y = traversed.surface_at(field, ray.origin, ray.direction, b);
        EXPECT_EQ(x.normal, y.normal) << "ray " << r;
        EXPECT_EQ(x.color, y.color) << "ray " << r;
        EXPECT_EQ(x.source, y.source) << "ray " << r;
      }
    }
  }
  // Both outcomes occur, and the traversal does leave sources out, so the
  // agreement means something.
  EXPECT_GT(hits, 50);
  EXPECT_GT(misses, 50);
  EXPECT_GT(pruned, 50);
}

TEST_F(CrowdScene, AmbientRaysGiveTheSameAnswersListedOrOneByOne) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> unit(-0.02, 0.02);
  std::vector<RayInterval> rays;
  for (int r = 0; r < 32; ++r)
    rays.push_back({Vec3(0.1 + unit(rng), unit(rng), 0.3 + unit(rng)), random_direction(rng), 0.0, 0.25});
  FieldRayLanes tracers;
  AmbientRays with_list, one_by_one;
  TraceStats listed_stats, traversed_stats;
  std::vector<std::uint8_t> listed, traversed;
  const std::vector<const SupportPlanes*> no_planes(rays.size(), nullptr);  // the rays leave no glyph hit
  with_list.trace(scene, rays, no_planes, 100.0, tracers, listed_stats, listed);  // a dense crowd: worth a list
  one_by_one.trace(scene, rays, no_planes, 0.0, tracers, traversed_stats, traversed);  // nothing there: one by one
  EXPECT_EQ(listed, traversed);
  EXPECT_EQ(listed_stats.span_queries, 0u);                 // no ray traversed the BVH
  EXPECT_EQ(traversed_stats.span_queries, rays.size());     // every ray did
  // The traversal stops at the first source a blocked ray enters; the list
  // hands every ray all its sources.
  EXPECT_LT(traversed_stats.spans, listed_stats.spans);
  const auto blocked = std::count(listed.begin(), listed.end(), 1);
  EXPECT_GT(blocked, 0);
  EXPECT_LT(blocked, std::ptrdiff_t(rays.size()));
}

// A union draws only each source's own level surface: the span BVH lists a
// source by that surface's box, and a ray's crossing is still the earliest
// single-source entry over all sources, found from the few whose level box
// it crosses. Every source whose support holds the crossing point has its
// influence box entered before it, yet only the winner matters: normal and
// colour are that source's.
TEST(UnionScene, ListsEachSourceByItsLevelSurfacesBoxAndFindsTheSameCrossings) {
  const EmbreeDevice device;
  BlobField field = crowd(300, 4);
  field.blend = Blend::max;
  for (std::size_t i = 0; i < field.sources.size(); ++i)
    field.sources[i].color = {float(i % 7) / 7.0f, 0.5f, float(i % 3) / 3.0f};
  const RayScene scene{device, field, TraceSettings{Intersector::exact}};
  const BlobGeometry& blobs = scene.blobs();
  const double level = kernel_level_radius(field.kernel, field.isovalue);
  ASSERT_LT(level, 0.9);
  for (std::size_t i = 0; i < field.sources.size(); ++i) {
    const Box3 influence = influence_bounds(field, i), listed = blobs.listed_bounds(i);
    const Vec3 c(field.sources[i].centre[0], field.sources[i].centre[1], field.sources[i].centre[2]);
    ASSERT_TRUE((listed.hi - c).isApprox(level * (influence.hi - c), 1e-12)) << i;
    ASSERT_TRUE((c - listed.lo).isApprox(level * (c - influence.lo), 1e-12)) << i;
  }
  const Box3 region{Vec3(-0.1, -0.05, -0.1), Vec3(0.15, 0.1, 0.05)};
  NearbySources list;
  std::vector<std::uint32_t> scratch;
  ASSERT_TRUE(blobs.gather_nearby(region, field.sources.size(), list, scratch));
  std::set<std::uint32_t> expected;
  std::size_t influencing = 0;
  for (std::uint32_t i = 0; i < field.sources.size(); ++i) {
    if (blobs.listed_bounds(i).overlaps(region)) expected.insert(i);
    influencing += influence_bounds(field, i).overlaps(region);
  }
  EXPECT_EQ(std::set<std::uint32_t>(scratch.begin(), scratch.end()), expected);
  EXPECT_GT(expected.size(), 10u);
  EXPECT_LT(expected.size(), influencing * 3 / 4);

  std::mt19937 rng(8);
  std::uniform_real_distribution<double> unit(-0.3, 0.3);
  FieldRay tracer;
  TraceStats stats;
  const double g_level = level * level;
  int hits = 0;
  for (int r = 0; r < 300; ++r) {
    const RayInterval ray{Vec3(unit(rng), unit(rng), 0.6), (Vec3(unit(rng), unit(rng), -1.0)).normalized(), 0.0,
                          2.0};
    // Every source on its own: the earliest entry into its level surface.
    double earliest = -1.0;
    std::uint32_t winner = 0;
    for (std::uint32_t i = 0; i < field.sources.size(); ++i) {
      RaySpan span;
      if (!ray_span(field.sources[i], i, i, ray.origin, ray.direction, ray.tmin, ray.tmax, span)) continue;
      const double t = single_source_entry(span, g_level, ray.tmin, ray.tmax);
      if (t >= 0.0 && (earliest < 0.0 || t < earliest)) earliest = t, winner = i;
    }
    const double t = blobs.first_crossing_traversed(ray, tracer, stats);
    ASSERT_EQ(t >= 0.0, earliest >= 0.0) << "ray " << r;
    if (t < 0.0) continue;
    ++hits;
    EXPECT_NEAR(t, earliest, 1e-12) << "ray " << r;
    const SurfaceSample s = tracer.surface_at(field, ray.origin, ray.direction, t);
    EXPECT_EQ(s.color, field.sources[winner].color) << "ray " << r;
    // The normal is the winner's own, ∇g = 2 Wᵀ q, though only the winner
    // is evaluated among the sources there.
    const Vec3 x = ray.origin + t * ray.direction;
    const Mat3 w = shape_matrix(field.sources[winner]);
    const Vec3 gradient = 2.0 * w.transpose() * scaled_offset(field.sources[winner], w, x);
    EXPECT_LT((s.normal - gradient.normalized()).norm(), 1e-9) << "ray " << r;
    EXPECT_GE(s.crowd, 1u);
  }
  EXPECT_GT(hits, 100);
}

}  // namespace
}  // namespace hsb
