// The colour scalar's extremes over the data's own values
// (field/glyphs/data_extremes.h), for the colour bar to mark where the
// glyphs do not reach them.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "field/glyphs/data_extremes.h"
#include "field/sampling/point_load.h"
#include "field/sampling/uniform_grid.h"
#include "field/tensor/eigensystem.h"

namespace hsb {
namespace {

// A 2×2×2 grid: a uniaxial tension of 5 along x, a compression of −7
// along z, two zero tensors (no data) and a NaN one (no body).
UniformGridField grid() {
  const double nan = std::nan("");
  std::vector<Sym3> values{Sym3{5, 0, 0, 0, 0, 0}, Sym3{0, 0, -7, 0, 0, 0}, Sym3{1, 1, 1, 0, 0, 0}, Sym3{},
                           Sym3{}, Sym3{nan, 0, 0, 0, 0, 0}, Sym3{2, 0, 0, 0, 0, 0}, Sym3{0, 3, 0, 0, 0, 0}};
  return UniformGridField(Vec3::Zero(), Vec3::Ones(), {2, 2, 2}, std::move(values));
}

TEST(DataExtremes, TheTensorsHeldGiveTheColoursExtremes) {
  const UniformGridField g = grid();
  const auto l1 = data_color_extremes(g, ColorScalar::lambda1);
  ASSERT_TRUE(l1);
  EXPECT_EQ((*l1)[0], 0.0);  // λ1 of the compression (its others are 0)
  EXPECT_EQ((*l1)[1], 5.0);
  const auto l3 = data_color_extremes(g, ColorScalar::lambda3);
  ASSERT_TRUE(l3);
  EXPECT_EQ((*l3)[0], -7.0);
  EXPECT_EQ((*l3)[1], 1.0);  // the zero tensors are no data: λ3 = 0 would not count, the isotropic 1 does
  // A family's eigenvalue: the least λ3 (compression lines) and the
  // largest λ1 (tension lines).
  const auto family = data_color_extremes(g, ColorScalar::family_eigenvalue);
  ASSERT_TRUE(family);
  EXPECT_EQ((*family)[0], -7.0);
  EXPECT_EQ((*family)[1], 5.0);
  const auto mises = data_color_extremes(g, ColorScalar::von_mises);
  ASSERT_TRUE(mises);
  EXPECT_NEAR((*mises)[1], 7.0, 1e-12);
  EXPECT_NEAR((*mises)[0], 0.0, 1e-12);  // the isotropic tensor
}

TEST(DataExtremes, NoneWhereTheDataHasNoValuesOrTheColourIsNotTheTensors) {
  EXPECT_FALSE(data_color_extremes(PointLoadField(PointLoadSpec{}), ColorScalar::lambda3));  // analytic
  const UniformGridField g = grid();
  EXPECT_FALSE(data_color_extremes(g, ColorScalar::fa));         // bounded: the bar spans [0, 1]
  EXPECT_FALSE(data_color_extremes(g, ColorScalar::direction));  // a colour, no bar
  EXPECT_FALSE(data_color_extremes(g, ColorScalar::array));      // not the tensor's
  const UniformGridField empty(Vec3::Zero(), Vec3::Ones(), {2, 2, 2}, std::vector<Sym3>(8));
  EXPECT_FALSE(data_color_extremes(empty, ColorScalar::lambda1));  // all zero: no data
}


// The extremes from every tensor's eigenvalues, as the colour bar takes
// them without any bound.
std::array<double, 2> every_tensors(const std::vector<Sym3>& values, ColorScalar low, ColorScalar high) {
  std::array<double, 2> r{INFINITY, -INFINITY};
  for (const Sym3& t : values) {
    if (!t.holds_data()) continue;
    const Vec3 l = eigenvalues(t);
    r[0] = std::min(r[0], color_scalar(l, low));
    r[1] = std::max(r[1], color_scalar(l, high));
  }
  return r;
}

// Most tensors are decided by bounds of their eigenvalues, not decomposed:
// the extremes are still those of every tensor, to the bit, on 40,000
// turned tensors of all signs and sizes, with extremes off the diagonal,
// ties (diagonal tensors sharing the largest and the least entries) and
// near-ties a hair inside them.
TEST(DataExtremes, TheBoundsLeaveTheExtremesAsEveryTensorGivesThem) {
  std::vector<Sym3> values;
  std::uint64_t state = 12345;
  const auto uniform = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < 40000; ++i) {
    const double size = std::pow(10.0, 6.0 * uniform() - 3.0);
    const Vec3 axis = Vec3(uniform() - 0.5, uniform() - 0.5, uniform() - 0.5).normalized();
    const Mat3 r = Eigen::AngleAxisd(6.3 * uniform(), axis).toRotationMatrix();
    const Vec3 l = size * Vec3(uniform() - 0.5, uniform() - 0.5, uniform() - 0.5);
    values.push_back(Sym3::symmetric_part(r * l.asDiagonal() * r.transpose()));
  }
  // The extremes off the diagonal: λ1 = 1200 and λ3 = −1200 where no
  // diagonal entry passes 600, beside diagonal tensors of ±1000.
  values.push_back(Sym3{600, 600, 0, 600, 0, 0});
  values.push_back(Sym3{-600, -600, 0, -600, 0, 0});
  for (int i = 0; i < 5; ++i) {
    values.push_back(Sym3{1e3, -1e3, 0.5, 0, 0, 0});
    values.push_back(Sym3{1e3 * (1.0 - 1e-15), -1e3 * (1.0 - 1e-15), 0.5, 1e-14, 0, 0});
  }
  do values.push_back(Sym3{});  // no data, to fill the grid's last row
  while (values.size() % 4 != 0);
  const UniformGridField field(Vec3::Zero(), Vec3::Ones(), {int(values.size() / 4), 2, 2}, values);
  for (const ColorScalar color : {ColorScalar::lambda1, ColorScalar::lambda2, ColorScalar::lambda3,
                                  ColorScalar::family_eigenvalue, ColorScalar::von_mises}) {
    const bool families = color == ColorScalar::family_eigenvalue;
    const auto expected =
        every_tensors(values, families ? ColorScalar::lambda3 : color, families ? ColorScalar::lambda1 : color);
    const auto found = data_color_extremes(field, color);
    ASSERT_TRUE(found) << color_scalar_name(color);
    EXPECT_EQ((*found)[0], expected[0]) << color_scalar_name(color);
    EXPECT_EQ((*found)[1], expected[1]) << color_scalar_name(color);
  }
}

}  // namespace
}  // namespace hsb
