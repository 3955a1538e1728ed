#pragma once
// Lights and surface response. Colours here are scene-linear RGB.

#include <array>

#include "field/sym3.h"

namespace hsb {

using Rgb = std::array<float, 3>;

struct ShadingSpec {
  Vec3 light_from{1.0, -1.5, 2.5};  // direction from the scene towards the key light
  Rgb light_color{1, 1, 1};
  double light_intensity = 1.0;
  bool shadows = true;
  double ambient = 0.3;    // uniform ambient light, times the surface colour
  double specular = 0.2;   // Blinn–Phong highlight strength
  double shininess = 40.0;
  Rgb background{1, 1, 1};
  Rgb box_color{0.05f, 0.05f, 0.05f};  // the domain's edges, when drawn
  // A data set's boundary surface, when drawn, is a translucent shell; its
  // opacity rises towards grazing angles, so the outline reads as an edge.
  Rgb shell_color{0.6f, 0.65f, 0.7f};
  double shell_opacity = 0.08;       // facing the viewer
  double shell_edge_opacity = 0.6;   // at grazing angles
};

// Light leaving a glyph surface point towards the viewer.
// `to_light` is unit; `visibility` is 0 in shadow, 1 lit.
Rgb shade_surface(const ShadingSpec& spec, const Rgb& albedo, const Vec3& normal,
                  const Vec3& to_viewer, const Vec3& to_light, double visibility);

}  // namespace hsb
