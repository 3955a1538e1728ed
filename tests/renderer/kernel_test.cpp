// The kernels' defining conditions (paper eq. 10) and the slope bounds the
// sphere tracer relies on.

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/surface/kernel.h"

namespace hsb {
namespace {

constexpr KernelKind all_kernels[] = {KernelKind::wyvill, KernelKind::quartic, KernelKind::blinn};

double k_of_u(KernelKind kind, double u) { return kernel_value(kind, u * u); }
double dk_du(KernelKind kind, double u) { return 2.0 * u * kernel_slope(kind, u * u); }

TEST(Kernel, WyvillSatisfiesThePapersFiveConditions) {
  const KernelKind w = KernelKind::wyvill;
  EXPECT_DOUBLE_EQ(k_of_u(w, 0.0), 1.0);                // I(0) = 1
  EXPECT_NEAR(k_of_u(w, 0.5), 0.5, 1e-15);               // I(R/2) = 1/2
  EXPECT_NEAR(kernel_value(w, 1.0 - 1e-15), 0.0, 1e-13); // I(R) = 0, continuously
  EXPECT_DOUBLE_EQ(dk_du(w, 0.0), 0.0);                  // I'(0) = 0
  EXPECT_NEAR(dk_du(w, 1.0 - 1e-12), 0.0, 1e-10);        // I'(R) = 0
  EXPECT_EQ(k_of_u(w, 1.5), 0.0);                        // compact support
}

TEST(Kernel, AllKernelsAreOneAtTheCentreZeroAtTheRimAndDecreasing) {
  for (KernelKind kind : all_kernels) {
    SCOPED_TRACE(kernel_name(kind));
    EXPECT_NEAR(k_of_u(kind, 0.0), 1.0, 1e-15);
    EXPECT_NEAR(kernel_value(kind, 1.0 - 1e-14), 0.0, 1e-12);
    EXPECT_EQ(kernel_value(kind, 1.0), 0.0);
    EXPECT_EQ(kernel_slope(kind, 1.0), 0.0);
    double previous = 2.0;
    for (int i = 0; i <= 1000; ++i) {
      const double k = k_of_u(kind, i / 1000.0);
      EXPECT_LT(k, previous);
      previous = k;
    }
  }
}

TEST(Kernel, BlinnIsHalfAtHalfLikeWyvill) {
  EXPECT_NEAR(k_of_u(KernelKind::blinn, 0.5), 0.5, 1e-12);
  EXPECT_NEAR(kernel_level_radius(KernelKind::blinn, 0.5), 0.5, 1e-12);
  EXPECT_NEAR(kernel_level_radius(KernelKind::wyvill, 0.5), 0.5, 1e-12);
  // quartic: (1 − u²)² = ½  ⇔  u = √(1 − 1/√2).
  EXPECT_NEAR(kernel_level_radius(KernelKind::quartic, 0.5), std::sqrt(1.0 - 1.0 / std::sqrt(2.0)),
              1e-12);
}

TEST(Kernel, SlopeIsTheDerivativeOfTheValue) {
  for (KernelKind kind : all_kernels) {
    SCOPED_TRACE(kernel_name(kind));
    for (double g = 0.01; g < 0.99; g += 0.07) {
      const double h = 1e-6;
      const double numeric = (kernel_value(kind, g + h) - kernel_value(kind, g - h)) / (2 * h);
      EXPECT_NEAR(kernel_slope(kind, g), numeric, 1e-7);
    }
  }
}

TEST(Kernel, MaxSlopeConstantIsATightUpperBound) {
  for (KernelKind kind : all_kernels) {
    SCOPED_TRACE(kernel_name(kind));
    double sampled = 0.0;
    for (int i = 0; i <= 200000; ++i) sampled = std::max(sampled, std::fabs(dk_du(kind, i / 200000.0)));
    EXPECT_GE(kernel_max_du_slope(kind), sampled);
    EXPECT_LT(kernel_max_du_slope(kind), sampled * (1.0 + 1e-9));
  }
}

}  // namespace
}  // namespace hsb
