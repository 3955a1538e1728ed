#include "renderer/image/colormap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsb {
namespace {

Rgb bytes(int r, int g, int b) { return {float(r) / 255.0f, float(g) / 255.0f, float(b) / 255.0f}; }

Colormap make_viridis() {
  // matplotlib's viridis (van der Walt and Smith) at nine evenly spaced
  // points (#440154 … #FDE725), interpolated linearly in between.
  return {"viridis",
          {bytes(68, 1, 84), bytes(71, 45, 123), bytes(59, 82, 139), bytes(44, 114, 142),
           bytes(33, 144, 140), bytes(39, 173, 129), bytes(93, 200, 99), bytes(170, 220, 50),
           bytes(253, 231, 37)},
          false};
}

Colormap make_coolwarm() {
  // Moreland's smooth cool–warm diverging map ("Diverging Color Maps for
  // Scientific Visualization", 2009), 33 samples.
  return {"coolwarm",
          {bytes(59, 76, 192),   bytes(68, 90, 204),   bytes(77, 104, 215),  bytes(87, 117, 225),
           bytes(98, 130, 234),  bytes(108, 142, 241), bytes(119, 154, 247), bytes(130, 165, 251),
           bytes(141, 176, 254), bytes(152, 185, 255), bytes(163, 194, 255), bytes(174, 201, 253),
           bytes(184, 208, 249), bytes(194, 213, 244), bytes(204, 217, 238), bytes(213, 219, 230),
           bytes(221, 221, 221), bytes(229, 216, 209), bytes(236, 211, 197), bytes(241, 204, 185),
           bytes(245, 196, 173), bytes(247, 187, 160), bytes(247, 177, 148), bytes(247, 166, 135),
           bytes(244, 154, 123), bytes(241, 141, 111), bytes(236, 127, 99),  bytes(229, 112, 88),
           bytes(222, 96, 77),   bytes(213, 80, 66),   bytes(203, 62, 56),   bytes(192, 40, 47),
           bytes(180, 4, 38)},
          true};
}

}  // namespace

Rgb Colormap::at(double u) const {
  if (!(u >= 0.0)) u = 0.0;  // also catches NaN
  u = std::min(u, 1.0);
  const double x = u * double(table.size() - 1);
  const std::size_t i = std::min(std::size_t(x), table.size() - 2);
  const float f = float(x - double(i));
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = table[i][c] + f * (table[i + 1][c] - table[i][c]);
  return out;
}

const std::vector<std::string>& colormap_names() {
  static const std::vector<std::string> names{"viridis", "coolwarm"};
  return names;
}

const Colormap& colormap_named(const std::string& name) {
  static const Colormap viridis = make_viridis();
  static const Colormap coolwarm = make_coolwarm();
  if (name == "viridis") return viridis;
  if (name == "coolwarm") return coolwarm;
  throw std::invalid_argument("unknown colormap \"" + name + "\"");
}

double ColorScale::normalized(double value) const { return (value - lo) / (hi - lo); }

namespace {

// The q-quantile (q ∈ [0, 1]) of `values`, by nearest rank.
double quantile(std::vector<double> values, double q) {
  const std::size_t k = std::min(values.size() - 1, std::size_t(q * double(values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

}  // namespace

ColorScale auto_scale(const Colormap& map, const std::vector<double>& values) {
  ColorScale scale{&map, 0.0, 1.0};
  if (values.empty()) return scale;
  if (map.diverging) {
    std::vector<double> magnitudes(values.size());
    std::transform(values.begin(), values.end(), magnitudes.begin(), [](double v) { return std::fabs(v); });
    const double m = quantile(std::move(magnitudes), 0.98);
    scale.lo = -m;
    scale.hi = m;
  } else {
    scale.lo = quantile(values, 0.02);
    scale.hi = quantile(values, 0.98);
  }
  if (!(scale.hi > scale.lo)) {
    const double pad = std::max(1.0, std::fabs(scale.lo)) * 1e-6;
    scale.lo -= pad;
    scale.hi += pad;
  }
  return scale;
}

}  // namespace hsb
