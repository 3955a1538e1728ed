#include "renderer/image/shape_key.h"

#include <cmath>

#include "renderer/surface/glyph_shape.h"

namespace hsb {
namespace {

// Points on an outline: enough that a 20-point glyph printed at 600 dpi
// shows no facet, and a multiple of 4 so each axis' end (a cone's point)
// is a vertex.
constexpr int kOutlinePoints = 720;

ShapeKeyEntry sample(const std::string& label, const Vec3& radii, const Vec3& eigenvalues, double sharpness) {
  // The physical sign is given, so the convention is the mechanics one.
  const ShapeParams params = signed_params(radii, eigenvalues, sharpness, SignConvention::tension_positive);
  const double largest = radii.maxCoeff();
  ShapeKeyEntry entry{label, {}};
  entry.outline.reserve(kOutlinePoints);
  for (int i = 0; i < kOutlinePoints; ++i) {
    const double angle = 2.0 * M_PI * i / kOutlinePoints;
    const Vec3 direction(std::cos(angle), std::sin(angle), 0.0);  // in the glyph's scaled frame q
    // u is a gauge (homogeneous of degree one), so the surface u = 1 lies
    // at direction / u(direction); shape_g reads q_s = q / σ.
    const double u = std::sqrt(shape_g(GlyphShape::signed_superquadric, params, direction / params.bound_scale));
    entry.outline.push_back({radii[0] * direction[0] / (u * largest), radii[1] * direction[1] / (u * largest)});
  }
  return entry;
}

}  // namespace

std::vector<ShapeKeyEntry> signed_shape_key(double sharpness) {
  // Radii of a glyph twice as long as it is wide, as along a stress
  // trajectory; the third axis, seen end on, is as wide as the second.
  const Vec3 slender(1.0, 0.5, 0.5), shear(1.0, 0.75, 0.5);
  return {sample("tension", slender, Vec3(1.0, 0.5, 0.5), sharpness),
          sample("compression", slender, Vec3(-1.0, -0.5, -0.5), sharpness),
          sample("shear", shear, Vec3(1.0, -0.75, 0.5), sharpness)};
}

}  // namespace hsb
