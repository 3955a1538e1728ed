// The context drawn around the glyphs, intersected in double precision:
// tubes (capsules) and the shell's triangles.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "renderer/render/context_lines.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/shell_geometry.h"

namespace hsb {
namespace {

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double s = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + s * ab)).norm();
}

// The entry the capsule test finds is on the capsule (at distance r from
// the segment) with the ray outside just before it; a ray it says misses
// never comes within r. Checked against dense sampling along each ray.
TEST(ContextLines, CapsuleEntriesAgreeWithTheDistanceToTheSegment) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int hits = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a(unit(rng), unit(rng), unit(rng)), b = a + 0.8 * Vec3(unit(rng), unit(rng), unit(rng));
    const double r = 0.05 + 0.2 * (unit(rng) + 1.0);
    const Vec3 o = 3.0 * Vec3(unit(rng), unit(rng), unit(rng)).normalized();
    const Vec3 d = (0.5 * (a + b) + 0.4 * Vec3(unit(rng), unit(rng), unit(rng)) - o).normalized();
    Vec3 normal;
    const double t = ray_capsule(o, d, a, b, r, 0.0, INFINITY, normal);
    // The nearest approach, sampled finely.
    double nearest = INFINITY, t_first_inside = -1.0;
    for (int k = 0; k <= 20000; ++k) {
      const double s = 8.0 * k / 20000.0;
      const double dist = distance_to_segment(o + s * d, a, b);
      nearest = std::min(nearest, dist);
      if (dist <= r && t_first_inside < 0.0) t_first_inside = s;
    }
    if (t < 0.0) {
      EXPECT_GT(nearest, r - 1e-6) << "trial " << trial;
      continue;
    }
    ++hits;
    const Vec3 p = o + t * d;
    EXPECT_NEAR(distance_to_segment(p, a, b), r, 1e-9 * (1.0 + r)) << "trial " << trial;
    EXPECT_NEAR(t, t_first_inside, 8.0 / 20000.0 + 1e-9) << "trial " << trial;
    EXPECT_NEAR(normal.norm(), 1.0, 1e-12);
    EXPECT_LT(normal.dot(d), 1e-9) << "the normal faces the ray at an entry";
  }
  EXPECT_GT(hits, 500);
}

TEST(ContextLines, AnIntervalThatEndsBeforeTheTubeMissesIt) {
  Vec3 normal;
  const Vec3 o(0, 0, -5), d(0, 0, 1), a(-1, 0, 0), b(1, 0, 0);
  EXPECT_NEAR(ray_capsule(o, d, a, b, 0.1, 0.0, INFINITY, normal), 4.9, 1e-12);
  EXPECT_LT(ray_capsule(o, d, a, b, 0.1, 0.0, 4.8, normal), 0.0);
  EXPECT_LT(ray_capsule(o, d, a, b, 0.1, 5.0, INFINITY, normal), 0.0);  // starts inside: no entry
  // Along the axis: the ball at the near end.
  EXPECT_NEAR(ray_capsule(Vec3(-5, 0, 0), Vec3(1, 0, 0), a, b, 0.1, 0.0, INFINITY, normal), 3.9, 1e-12);
  EXPECT_NEAR(normal.x(), -1.0, 1e-12);
}

// A closed surface made of triangles: the octahedron's faces, each split
// into four so that edges and vertices are shared several ways.
TriangleMesh closed_mesh() {
  TriangleMesh mesh;
  const Vec3 v[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const auto& f : faces) {
    const Vec3 a = v[f[0]], b = v[f[1]], c = v[f[2]];
    const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
    for (const std::array<Vec3, 3>& t : {std::array<Vec3, 3>{a, ab, ca}, std::array<Vec3, 3>{ab, b, bc},
                                         std::array<Vec3, 3>{ca, bc, c}, std::array<Vec3, 3>{ab, bc, ca}}) {
      const std::uint32_t first = std::uint32_t(mesh.vertices.size());
      for (const Vec3& p : t) mesh.vertices.push_back(p);
      mesh.triangles.push_back({first, first + 1, first + 2});
    }
  }
  return mesh;
}

// Every ray that passes through the closed surface crosses it exactly
// twice, also through its edges and vertices, where several triangles
// meet: the shell's layers are never doubled or dropped (specks).
TEST(ShellGeometry, RaysThroughEdgesAndVerticesCrossAClosedSurfaceTwice) {
  const TriangleMesh mesh = closed_mesh();
  const EmbreeDevice device;
  const ShellGeometry shell(device.get(), mesh);
  std::vector<ShellCrossing> layers;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int through = 0;
  for (int k = 0; k < 3000; ++k) {
    // Aim at a vertex, an edge's midpoint or a random point inside.
    Vec3 target;
    const std::size_t tri = std::size_t(rng() % mesh.triangles.size());
    const Vec3 a = mesh.vertices[mesh.triangles[tri][0]], b = mesh.vertices[mesh.triangles[tri][1]];
    switch (k % 3) {
      case 0: target = a; break;
      case 1: target = 0.5 * (a + b); break;
      default: target = 0.3 * Vec3(unit(rng), unit(rng), unit(rng)); break;
    }
    const Vec3 o = 4.0 * Vec3(unit(rng), unit(rng), unit(rng)).normalized();
    const Vec3 d = (target - o).normalized();
    shell.crossings(o, d, INFINITY, 8, layers);
    // The octahedron is |x| + |y| + |z| ≤ 1; along the ray that sum is
    // convex and piecewise linear, smallest where a coordinate is zero.
    double least = INFINITY;
    for (int c = 0; c < 3; ++c) {
      const double t = std::max(0.0, -o[c] / d[c]);
      least = std::min(least, (o + t * d).cwiseAbs().sum());
    }
    if (least < 1.0 - 1e-9) {
      ASSERT_EQ(layers.size(), 2u) << "ray " << k << " aimed at " << target.transpose();
      EXPECT_LT(layers[0].t, layers[1].t);
      ++through;
    } else if (least > 1.0 + 1e-9) {
      EXPECT_TRUE(layers.empty()) << "ray " << k;
    } else {
      EXPECT_LE(layers.size(), 1u) << "ray " << k << " only touches the surface";
    }
  }
  EXPECT_GT(through, 2000);
}

TEST(ShellGeometry, LayersStopAtTheGivenDepthAndAtTheLimit) {
  const TriangleMesh mesh = closed_mesh();
  const EmbreeDevice device;
  const ShellGeometry shell(device.get(), mesh);
  std::vector<ShellCrossing> layers;
  const Vec3 o(0.1, 0.05, -4), d(0, 0, 1);
  shell.crossings(o, d, INFINITY, 8, layers);
  ASSERT_EQ(layers.size(), 2u);
  EXPECT_NEAR(layers[0].t, 4.0 - (1.0 - 0.15), 1e-12);  // the face x + y − z = 1 below
  EXPECT_NEAR(std::fabs(layers[0].normal.dot(Vec3(1, 1, -1).normalized())), 1.0, 1e-12);
  shell.crossings(o, d, 4.0, 8, layers);
  EXPECT_EQ(layers.size(), 1u);
  shell.crossings(o, d, INFINITY, 1, layers);
  EXPECT_EQ(layers.size(), 1u);
}

}  // namespace
}  // namespace hsb
