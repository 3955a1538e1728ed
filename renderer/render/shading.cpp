#include "renderer/render/shading.h"

#include <algorithm>
#include <cmath>

namespace hsb {

Rgb shade_surface(const ShadingSpec& spec, const Rgb& albedo, const Vec3& normal,
                  const Vec3& to_viewer, const Vec3& to_light, double visibility) {
  // A surface seen from inside (the camera in a glyph) is lit as its outside.
  const Vec3 n = normal.dot(to_viewer) < 0.0 ? Vec3(-normal) : normal;
  const double diffuse = std::max(0.0, n.dot(to_light)) * visibility;
  const Vec3 half = (to_light + to_viewer).normalized();
  const double highlight =
      diffuse > 0.0 ? spec.specular * std::pow(std::max(0.0, n.dot(half)), spec.shininess) : 0.0;
  Rgb out;
  for (int c = 0; c < 3; ++c) {
    const double light = spec.light_intensity * spec.light_color[c];
    out[c] = static_cast<float>(albedo[c] * (spec.ambient + light * diffuse) + light * highlight);
  }
  return out;
}

}  // namespace hsb
