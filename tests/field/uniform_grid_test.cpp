// Trilinear interpolation on the six components: exact at nodes and for
// affine fields, nothing outside, and a faithful copy of a sampled field.

#include "field/sampling/uniform_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "field/sampling/point_load.h"

namespace hsb {
namespace {

// Six different affine functions of position, one per component.
Sym3 affine(const Vec3& p) {
  return {1.0 + 2.0 * p.x() - p.y() + 0.5 * p.z(),  -3.0 + 0.25 * p.x() + 4.0 * p.y(),
          0.5 - p.z() + 1.5 * p.x(),                2.0 * p.y() - 3.0 * p.z(),
          -1.0 + 0.1 * p.x() + 0.2 * p.y() + 0.3 * p.z(), 7.0 - 5.0 * p.x()};
}

struct AffineField final : TensorField {
  Box3 box;
  Box3 bounds() const override { return box; }
  std::optional<Sym3> sample(const Vec3& x) const override {
    if (!box.contains(x)) return std::nullopt;
    return affine(x);
  }
};

UniformGridField affine_grid(const Vec3& origin, const Vec3& spacing,
                             const std::array<int, 3>& dims) {
  std::vector<Sym3> values;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
        values.push_back(affine(origin + spacing.cwiseProduct(Vec3(i, j, k))));
  return UniformGridField(origin, spacing, dims, std::move(values));
}

// A point drawn uniformly from the box.
Vec3 random_point_in(const Box3& b, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return b.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(b.size());
}

double max_diff(const Sym3& a, const Sym3& b) {
  return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff();
}

const Vec3 kOrigin(-1.0, 0.5, 2.0);
const Vec3 kSpacing(0.25, 0.5, 0.125);
const std::array<int, 3> kDims{5, 4, 7};

TEST(UniformGrid, BoundsAndNodeOrder) {
  const UniformGridField g = affine_grid(kOrigin, kSpacing, kDims);
  EXPECT_EQ(g.bounds().lo, kOrigin);
  EXPECT_LE((g.bounds().hi - Vec3(0.0, 2.0, 2.75)).norm(), 1e-15);
  // x fastest: node(i, j, k) is the value written at that position.
  EXPECT_LE(max_diff(g.node(3, 2, 5), affine(kOrigin + kSpacing.cwiseProduct(Vec3(3, 2, 5)))),
            1e-15);
}

TEST(UniformGrid, ExactAtNodes) {
  const UniformGridField g = affine_grid(kOrigin, kSpacing, kDims);
  for (int k = 0; k < kDims[2]; ++k)
    for (int j = 0; j < kDims[1]; ++j)
      for (int i = 0; i < kDims[0]; ++i) {
        const Vec3 p = kOrigin + kSpacing.cwiseProduct(Vec3(i, j, k));
        const std::optional<Sym3> s = g.sample(p);
        ASSERT_TRUE(s.has_value()) << i << " " << j << " " << k;
        EXPECT_LE(max_diff(*s, g.node(i, j, k)), 1e-14) << i << " " << j << " " << k;
      }
}

TEST(UniformGrid, ReproducesAffineFieldsInside) {
  const UniformGridField g = affine_grid(kOrigin, kSpacing, kDims);
  std::mt19937 rng(5);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 p = random_point_in(g.bounds(), rng);
    const std::optional<Sym3> s = g.sample(p);
    ASSERT_TRUE(s.has_value());
    EXPECT_LE(max_diff(*s, affine(p)), 1e-12) << p.transpose();
  }
}

TEST(UniformGrid, FarFacesAreInside) {
  const UniformGridField g = affine_grid(kOrigin, kSpacing, kDims);
  const Box3 b = g.bounds();
  std::mt19937 rng(6);
  for (int a = 0; a < 3; ++a) {
    for (int i = 0; i < 50; ++i) {
      Vec3 p = random_point_in(b, rng);
      p(a) = b.hi(a);
      const std::optional<Sym3> s = g.sample(p);
      ASSERT_TRUE(s.has_value()) << "axis " << a;
      EXPECT_LE(max_diff(*s, affine(p)), 1e-12) << p.transpose();
    }
  }
  ASSERT_TRUE(g.sample(b.hi).has_value());
  EXPECT_LE(max_diff(*g.sample(b.hi), affine(b.hi)), 1e-12);
  ASSERT_TRUE(g.sample(b.lo).has_value());
}

TEST(UniformGrid, NothingOutside) {
  const UniformGridField g = affine_grid(kOrigin, kSpacing, kDims);
  const Box3 b = g.bounds();
  for (int a = 0; a < 3; ++a) {
    Vec3 below = b.centre(), above = b.centre();
    below(a) = b.lo(a) - 1e-6;
    above(a) = b.hi(a) + 1e-6;
    EXPECT_FALSE(g.sample(below).has_value()) << "axis " << a;
    EXPECT_FALSE(g.sample(above).has_value()) << "axis " << a;
  }
  EXPECT_FALSE(g.sample(Vec3(std::nan(""), 1.0, 2.5)).has_value());
}

TEST(UniformGrid, SampledFromPointLoadMatchesAtNodes) {
  PointLoadSpec spec;
  spec.bounds = {Vec3(-1.0, -0.7, -1.3), Vec3(0.9, 1.0, 0.7)};  // spacings not dyadic
  const PointLoadField f(spec);
  const std::array<int, 3> dims{11, 9, 13};
  const UniformGridField g = UniformGridField::sampled_from(f, dims);
  EXPECT_EQ(g.dims(), dims);
  EXPECT_LE((g.bounds().lo - spec.bounds.lo).norm(), 0.0);
  EXPECT_LE((g.bounds().hi - spec.bounds.hi).cwiseAbs().maxCoeff(), 1e-15);
  const Vec3 cells(dims[0] - 1, dims[1] - 1, dims[2] - 1);
  int load_nodes = 0;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) {
        const Vec3 p = spec.bounds.lo +
                       Vec3(i, j, k).cwiseQuotient(cells).cwiseProduct(spec.bounds.size());
        if ((p - f.load_point()).norm() < 1e-9) {
          // Inside the singular ball the value depends on the direction to
          // the load, so a position an ulp away is not comparable: check
          // the node against the field's own value at the load point.
          ++load_nodes;
          EXPECT_LE(max_diff(g.node(i, j, k), *f.sample(f.load_point())), 0.0);
          continue;
        }
        const Sym3 expected = f.stress(p);
        EXPECT_LE(max_diff(g.node(i, j, k), expected), 1e-12 * expected.frobenius_norm())
            << i << " " << j << " " << k;
      }
  EXPECT_EQ(load_nodes, 1);  // odd dims in x and y: a node sits on the load
  // Between nodes it is an interpolation, not a copy: far from the load the
  // field is smooth and the grid should be close.
  const Vec3 p(0.13, 0.21, -1.0);
  EXPECT_LE((g.sample(p)->matrix() - f.stress(p).matrix()).norm(),
            0.05 * f.stress(p).frobenius_norm());
}

TEST(UniformGrid, SampledFromAffineIsExact) {
  AffineField f;
  // With these bounds the far face in x maps to index 54.00000000000001,
  // not 54: rounding must not push the domain's own corner outside.
  f.box = {Vec3(-0.13, 0.1, 1.0), Vec3(0.9, 0.4, 1.9)};
  const UniformGridField g = UniformGridField::sampled_from(f, {55, 4, 5});
  for (const Vec3& corner : {f.box.lo, f.box.hi, g.bounds().hi}) {
    ASSERT_TRUE(g.sample(corner).has_value()) << corner.transpose();
    EXPECT_LE(max_diff(*g.sample(corner), affine(corner)), 1e-12);
  }
  std::mt19937 rng(8);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p = random_point_in(f.box, rng);
    ASSERT_TRUE(g.sample(p).has_value());
    EXPECT_LE(max_diff(*g.sample(p), affine(p)), 1e-12);
  }
}

TEST(UniformGrid, RejectsBadInput) {
  const std::vector<Sym3> eight(8);
  EXPECT_NO_THROW(UniformGridField(Vec3::Zero(), Vec3::Ones(), {2, 2, 2}, eight));
  EXPECT_THROW(UniformGridField(Vec3::Zero(), Vec3::Ones(), {1, 2, 4}, eight),
               std::invalid_argument);
  EXPECT_THROW(UniformGridField(Vec3::Zero(), Vec3::Ones(), {2, 2, 3}, eight),
               std::invalid_argument);
  EXPECT_THROW(UniformGridField(Vec3::Zero(), Vec3(1, 0, 1), {2, 2, 2}, eight),
               std::invalid_argument);
  EXPECT_THROW(UniformGridField(Vec3::Zero(), Vec3(1, -1, 1), {2, 2, 2}, eight),
               std::invalid_argument);
  std::vector<Sym3> bad = eight;
  bad[3].xy = std::numeric_limits<double>::infinity();
  EXPECT_THROW(UniformGridField(Vec3::Zero(), Vec3::Ones(), {2, 2, 2}, bad),
               std::invalid_argument);
  // Looked for across the threads' blocks: an infinite component anywhere
  // in a volume of several blocks, its last node included; NaN is no data.
  std::vector<Sym3> volume(std::size_t(64) * 64 * 64);
  volume[12345].zz = std::nan("");
  EXPECT_NO_THROW(UniformGridField(Vec3::Zero(), Vec3::Ones(), {64, 64, 64}, volume));
  for (const std::size_t at : {std::size_t(0), std::size_t(70000), volume.size() - 1})
    for (double Sym3::*component : {&Sym3::xx, &Sym3::yy, &Sym3::zz, &Sym3::xy, &Sym3::yz, &Sym3::xz}) {
      std::vector<Sym3> infinite = volume;
      infinite[at].*component = -std::numeric_limits<double>::infinity();
      EXPECT_THROW(UniformGridField(Vec3::Zero(), Vec3::Ones(), {64, 64, 64}, infinite), std::invalid_argument)
          << "node " << at;
    }
  const PointLoadField f(PointLoadSpec{});
  EXPECT_THROW(UniformGridField::sampled_from(f, {2, 1, 2}), std::invalid_argument);
  EXPECT_THROW(UniformGridField::sampled_from(f, {0, 0, 0}), std::invalid_argument);
}

// A field that refuses some of its own domain: sampled_from must say so
// rather than invent values.
struct HoleyField final : TensorField {
  Box3 bounds() const override { return {Vec3::Zero(), Vec3::Ones()}; }
  std::optional<Sym3> sample(const Vec3& x) const override {
    if (x.x() > 0.5) return std::nullopt;
    return Sym3{1, 1, 1, 0, 0, 0};
  }
};

TEST(UniformGrid, SampledFromUnsampleableNodeThrows) {
  EXPECT_THROW(UniformGridField::sampled_from(HoleyField{}, {3, 3, 3}), std::runtime_error);
}

}  // namespace
}  // namespace hsb
