// The tensor measures (tensor_measures.h) against their definitions on
// tensors whose values are known in closed form, and as colour scalars.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "field/glyphs/glyph_mapping.h"
#include "field/tensor/eigensystem.h"
#include "field/tensor/tensor_measures.h"

namespace hsb {
namespace {

TEST(TensorMeasures, AnisotropyIsOneForALineZeroForASphereAndInvariantToScale) {
  EXPECT_NEAR(fractional_anisotropy(Vec3(1, 0, 0)), 1.0, 1e-15);
  EXPECT_NEAR(fractional_anisotropy(Vec3(2, 2, 2)), 0.0, 1e-15);
  EXPECT_NEAR(fractional_anisotropy(Vec3(1, 1, 0)), std::sqrt(0.5), 1e-15);  // a disc
  EXPECT_EQ(fractional_anisotropy(Vec3::Zero()), 0.0);
  // White matter: 1.7, 0.3, 0.3 (×10⁻³ mm²/s) has FA 0.8 to two digits.
  const Vec3 fibre(1.7e-3, 0.3e-3, 0.3e-3);
  const double expected = std::sqrt(1.5) * std::sqrt(2 * 0.4667 * 0.4667 + 0.9333 * 0.9333) / std::sqrt(2.89 + 0.18);
  EXPECT_NEAR(fractional_anisotropy(fibre), expected, 1e-3);
  EXPECT_NEAR(fractional_anisotropy(fibre), fractional_anisotropy(1e6 * fibre), 1e-15);
  EXPECT_NEAR(fractional_anisotropy(fibre), fractional_anisotropy(1e-6 * fibre), 1e-15);
}

// The components' FA (which skips the decomposition for voxels far below a
// region's threshold) is the eigenvalues' FA to round-off, for tensors of
// any orientation, scale and sign.
TEST(TensorMeasures, AnisotropyFromTheComponentsIsTheEigenvaluesOwn) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    Sym3 t;
    t.xx = value(random), t.yy = value(random), t.zz = value(random);
    t.xy = value(random), t.yz = value(random), t.xz = value(random);
    if (i % 2) t.xx = std::fabs(t.xx) + 2, t.yy = std::fabs(t.yy) + 2, t.zz = std::fabs(t.zz) + 2;  // near isotropic
    const double scale = std::pow(10.0, double(i % 13) - 9.0);  // 1e-9 (m²/s) to 1e3 (MPa)
    const Sym3 scaled = scale * t;
    EXPECT_NEAR(fractional_anisotropy(scaled), fractional_anisotropy(decompose(scaled).values), 1e-14) << i;
  }
  EXPECT_EQ(fractional_anisotropy(Sym3{}), 0.0);
}

TEST(TensorMeasures, ModeTellsLinearFromPlanarAndTensionFromCompression) {
  EXPECT_NEAR(tensor_mode(Vec3(1, 0, 0)), 1.0, 1e-14);    // one larger eigenvalue: linear
  EXPECT_NEAR(tensor_mode(Vec3(1, 1, 0)), -1.0, 1e-14);   // two larger: planar
  EXPECT_NEAR(tensor_mode(Vec3(1, 0, -1)), 0.0, 1e-14);   // orthotropic, pure shear
  EXPECT_NEAR(tensor_mode(Vec3(0, 0, -5)), -1.0, 1e-14);  // uniaxial compression
  EXPECT_NEAR(tensor_mode(Vec3(5, 0, 0)), 1.0, 1e-14);    // uniaxial tension
  EXPECT_EQ(tensor_mode(Vec3(3, 3, 3)), 0.0);             // no deviator
  EXPECT_EQ(tensor_mode(Vec3(3, 3, 3 + 1e-15)), 0.0);     // only round-off of one
  // Adding an isotropic part changes nothing.
  EXPECT_NEAR(tensor_mode(Vec3(3, 1, 0.5)), tensor_mode(Vec3(13, 11, 10.5)), 1e-12);
}

TEST(TensorMeasures, WestinsMeasuresSumToOneOverTheMagnitudes) {
  const WestinMeasures w = westin_measures(Vec3(3, 2, 1));
  EXPECT_NEAR(w.linear, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(w.planar, 2.0 / 6.0, 1e-15);
  EXPECT_NEAR(w.spherical, 3.0 / 6.0, 1e-15);
  // In any order and of any sign: the glyph's radii.
  const WestinMeasures v = westin_measures(Vec3(-1, 3, -2));
  EXPECT_NEAR(v.linear, w.linear, 1e-15);
  EXPECT_NEAR(v.planar, w.planar, 1e-15);
  EXPECT_NEAR(v.spherical, w.spherical, 1e-15);
  EXPECT_NEAR(westin_measures(Vec3(1, 0, 0)).linear, 1.0, 1e-15);
  EXPECT_NEAR(westin_measures(Vec3(1, 1, 0)).planar, 1.0, 1e-15);
  EXPECT_EQ(westin_measures(Vec3::Zero()).spherical, 1.0);  // no shape: drawn as a sphere
}

TEST(TensorMeasures, EachIsAColourScalarWithItsRange) {
  const Vec3 l(1.7, 0.5, 0.2);
  EXPECT_EQ(color_scalar(l, ColorScalar::fa), fractional_anisotropy(l));
  EXPECT_EQ(color_scalar(l, ColorScalar::mode), tensor_mode(l));
  EXPECT_EQ(color_scalar(l, ColorScalar::trace), l.sum());
  EXPECT_EQ(color_scalar(l, ColorScalar::westin_linear), westin_measures(l).linear);
  EXPECT_EQ(color_scalar(l, ColorScalar::westin_planar), westin_measures(l).planar);
  EXPECT_EQ(color_scalar(l, ColorScalar::westin_spherical), westin_measures(l).spherical);
  for (ColorScalar c : {ColorScalar::fa, ColorScalar::westin_linear, ColorScalar::westin_planar,
                        ColorScalar::westin_spherical}) {
    ASSERT_TRUE(natural_range(c)) << color_scalar_name(c);
    EXPECT_EQ((*natural_range(c))[0], 0.0);
    EXPECT_EQ((*natural_range(c))[1], 1.0);
    EXPECT_TRUE(needs_tensors(c));
  }
  EXPECT_EQ((*natural_range(ColorScalar::mode))[0], -1.0);
  EXPECT_FALSE(natural_range(ColorScalar::trace));
  EXPECT_FALSE(natural_range(ColorScalar::lambda1));
  EXPECT_FALSE(needs_tensors(ColorScalar::speed));
  EXPECT_STREQ(color_scalar_name(ColorScalar::fa), "fa");
  EXPECT_STREQ(color_scalar_name(ColorScalar::westin_linear), "cl");
}

}  // namespace
}  // namespace hsb
