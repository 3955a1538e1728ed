// Telling diffusion from stress by the tensors alone (data_quantity.h).

#include <gtest/gtest.h>

#include "field/data_quantity.h"

namespace hsb {
namespace {

// n copies of `l`, and one indefinite tensor in ten for fitting noise.
std::vector<Vec3> field_of(const Vec3& l, bool noisy = false) {
  std::vector<Vec3> v(100, l);
  if (noisy)
    for (std::size_t i = 0; i < v.size(); i += 12) v[i] = Vec3(l(0), l(1), -0.1 * l(2));
  return v;
}

TEST(DataQuantity, WaterInTissueIsDiffusionInEveryUnit) {
  const Vec3 fibre(1.7, 0.3, 0.3);  // ×10⁻³ mm²/s
  EXPECT_EQ(recognised_quantity(field_of(1e-3 * fibre)), DataQuantity::diffusion);      // mm²/s
  EXPECT_EQ(recognised_quantity(field_of(1e-9 * fibre)), DataQuantity::diffusion);      // m²/s
  EXPECT_EQ(recognised_quantity(field_of(fibre)), DataQuantity::diffusion);             // µm²/ms
  EXPECT_EQ(recognised_quantity(field_of(1e-3 * fibre, true)), DataQuantity::diffusion);  // with noise
  EXPECT_EQ(recognised_quantity(field_of(Vec3::Constant(3e-3))), DataQuantity::diffusion);  // fluid
  // Zeros outside the brain's mask, as FSL writes them, however many.
  std::vector<Vec3> masked(300, Vec3::Zero());
  for (const Vec3& l : field_of(1e-3 * fibre)) masked.push_back(l);
  EXPECT_EQ(recognised_quantity(masked), DataQuantity::diffusion);
}

TEST(DataQuantity, StressIsStressEvenAtTheSameMagnitudes) {
  EXPECT_EQ(recognised_quantity(field_of(Vec3(1.0, 0.0, 0.0))), DataQuantity::stress);     // a bar in tension, MPa
  EXPECT_EQ(recognised_quantity(field_of(Vec3(2.0, 1.0, 0.0))), DataQuantity::stress);     // a plate, biaxial
  EXPECT_EQ(recognised_quantity(field_of(Vec3(1e-3, 0.0, -1e-3))), DataQuantity::stress);  // shear
  EXPECT_EQ(recognised_quantity(field_of(Vec3(3e7, 1e7, 5e6))), DataQuantity::stress);     // triaxial, Pa
  EXPECT_EQ(recognised_quantity(field_of(Vec3(-1, -2, -3))), DataQuantity::stress);        // compression
  EXPECT_EQ(recognised_quantity({}), DataQuantity::stress);
}

}  // namespace
}  // namespace hsb
