#include "renderer/image/direction_key.h"

#include <algorithm>
#include <cmath>

#include "renderer/image/colormap.h"

namespace hsb {

Rgb direction_srgb(const Vec3& direction, double weight) {
  const double w = std::clamp(weight, 0.0, 1.0);
  Rgb c;
  for (int k = 0; k < 3; ++k)
    c[std::size_t(k)] = float(w * std::min(1.0, std::fabs(direction[k])) + (1.0 - w) * kUncoloured[std::size_t(k)]);
  return c;
}

DirectionKey direction_key(const Vec3& right, const Vec3& up, const std::string& anatomical_frame) {
  DirectionKey key;
  for (int k = 0; k < 3; ++k) key.axes[std::size_t(k)] = {right[k], up[k]};
  if (anatomical_frame.size() == 3)
    for (std::size_t k = 0; k < 3; ++k) key.labels[k] = std::string(1, anatomical_frame[k]);
  return key;
}

}  // namespace hsb
