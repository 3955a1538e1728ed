// The float steps (base/float_steps.h) against std::nextafter, on the
// floats where stepping is special (zeros, the least and greatest, the
// infinities, NaN) and on a million others of every sign and exponent.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "base/bit_cast.h"
#include "base/float_steps.h"

namespace hsb {
namespace {

std::uint32_t bits(float x) { return bit_cast<std::uint32_t>(x); }

// The same float, to the bit; any NaN matches any NaN.
void expect_same(float got, float want, float from, const char* what) {
  if (std::isnan(want)) {
    EXPECT_TRUE(std::isnan(got)) << what << " of " << from;
    return;
  }
  EXPECT_EQ(bits(got), bits(want)) << what << " of " << from << ": " << got << " against " << want;
}

void expect_steps_match(float x) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  expect_same(float_up(x), std::nextafter(x, inf), x, "float_up");
  expect_same(float_down(x), std::nextafter(x, -inf), x, "float_down");
  expect_same(float_toward_zero(x), std::nextafter(x, 0.0f), x, "float_toward_zero");
}

TEST(FloatSteps, SpecialFloatsStepAsNextafterSays) {
  using limits = std::numeric_limits<float>;
  for (float x : {0.0f, -0.0f, limits::denorm_min(), -limits::denorm_min(), limits::min(), -limits::min(),
                  limits::max(), -limits::max(), limits::infinity(), -limits::infinity(), limits::quiet_NaN(), 1.0f,
                  -1.0f, limits::epsilon()})
    expect_steps_match(x);
}

TEST(FloatSteps, AMillionFloatsOfEverySignAndExponentStepAsNextafterSays) {
  std::mt19937 random(7);
  for (int i = 0; i < 1000000; ++i) {
    expect_steps_match(bit_cast<float>(std::uint32_t(random())));
  }
}

}  // namespace
}  // namespace hsb
