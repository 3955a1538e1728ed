// The colour scalar's extremes over the data's own values
// (field/glyphs/data_extremes.h), for the colour bar to mark where the
// glyphs do not reach them.

#include <gtest/gtest.h>

#include <cmath>

#include "field/glyphs/data_extremes.h"
#include "field/sampling/point_load.h"
#include "field/sampling/uniform_grid.h"

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

}  // namespace
}  // namespace hsb
