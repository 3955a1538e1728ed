#include "renderer/render/pixel_filter.h"

#include <array>
#include <cmath>
#include <cstddef>

namespace hsb {
namespace {

// Blackman–Harris (4-term, minimum side lobe) over [−r, r].
double blackman_harris(double d) {
  if (std::fabs(d) >= kFilterRadius) return 0.0;
  const double x = M_PI * (d / kFilterRadius + 1.0);  // 0 … 2π across the window
  return 0.35875 - 0.48829 * std::cos(x) + 0.14128 * std::cos(2.0 * x) - 0.01168 * std::cos(3.0 * x);
}

// The window tabulated once: every sample needs it 2 × 3 times, and
// cosines would show in the render. Linear interpolation between 4096
// entries is within 1e-6 of the window.
class WindowTable {
 public:
  WindowTable() {
    for (std::size_t i = 0; i < kEntries; ++i) table_[i] = blackman_harris(-kFilterRadius + double(i) * kStep);
  }
  double operator()(double d) const {
    const double x = (d + kFilterRadius) / kStep;
    if (!(x >= 0.0) || x >= double(kEntries - 1)) return 0.0;
    const std::size_t i = std::size_t(x);
    const double f = x - double(i);
    return table_[i] + f * (table_[i + 1] - table_[i]);
  }

 private:
  static constexpr std::size_t kEntries = 4097;
  static constexpr double kStep = 2.0 * kFilterRadius / double(kEntries - 1);
  std::array<double, kEntries> table_;
};

const WindowTable window;

}  // namespace

FilterTaps filter_taps(float sx, float sy) {
  FilterTaps taps;
  for (int d = -kFilterReach; d <= kFilterReach; ++d) {
    // The offset's sum in float, as the sample's position is kept.
    taps.x[d + kFilterReach] = window(float(d) + sx - 0.5);
    taps.y[d + kFilterReach] = window(float(d) + sy - 0.5);
  }
  return taps;
}

}  // namespace hsb
