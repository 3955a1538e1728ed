#include "renderer/render/shading.h"

#include <algorithm>
#include <cmath>

namespace hsb {
namespace {

double highlight(const ShadingSpec& spec, const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) {
  if (n.dot(to_light) <= 0.0) return 0.0;
  const Vec3 half = (to_light + to_viewer).normalized();
  return spec.specular * std::pow(std::max(0.0, n.dot(half)), spec.shininess);
}

}  // namespace

Rgb shade_surface(const ShadingSpec& spec, const Rgb& albedo, const Vec3& normal, const Vec3& to_viewer,
                  const Visibility& visibility) {
  // A surface seen from inside (the camera in a glyph) is lit as its outside.
  const Vec3 n = facing_normal(normal, to_viewer);
  const Vec3 key = spec.light_from.normalized(), fill = spec.fill_from.normalized();
  const double key_diffuse = std::max(0.0, n.dot(key)) * visibility.key;
  const double fill_diffuse = std::max(0.0, n.dot(fill));
  const double key_highlight = highlight(spec, n, key, to_viewer) * visibility.key;
  const double fill_highlight = highlight(spec, n, fill, to_viewer);
  Rgb out;
  for (int c = 0; c < 3; ++c) {
    const double key_light = spec.light_intensity * spec.light_color[c];
    const double irradiance = spec.ambient * visibility.ambient + key_light * key_diffuse +
                              spec.fill_intensity * fill_diffuse;
    out[c] = float(albedo[c] * irradiance + key_light * key_highlight + spec.fill_intensity * fill_highlight);
  }
  return out;
}

Rgb background_at(const ShadingSpec& spec, double v) {
  if (spec.background_kind != BackgroundKind::gradient) return spec.background;
  const float t = float(std::clamp(v, 0.0, 1.0));
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = (1.0f - t) * spec.background[c] + t * spec.background_bottom[c];
  return out;
}

}  // namespace hsb
