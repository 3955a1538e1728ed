#pragma once
// Lights and surface response. Colours here are scene-linear RGB.
//
// A key light with soft shadows (a disc of light, seen from the scene as
// `light_size` degrees across), a fill light from the other side that
// lifts the key's shadows without casting any, and ambient light shadowed
// by ambient occlusion, so a dense pile of glyphs reads as a shape and not
// a dark mass. Blinn–Phong highlights from both lights show curvature.
// Under ambient light of 1 alone, a surface's colour is its albedo: the
// colormap's colours reach the picture as defined.

#include "base/rgb.h"
#include "base/vec3.h"

namespace hsb {

enum class BackgroundKind { solid, gradient, transparent };

struct ShadingSpec {
  // Key light: direction from the scene towards it.
  Vec3 light_from{1.0, -1.5, 2.5};
  Rgb light_color{1, 1, 1};
  double light_intensity = 0.85;
  double light_size = 5.0;  // degrees across; 0: a point, hard shadows
  int light_samples = 4;    // shadow rays a camera sample sends to it
  bool shadows = true;
  // Fill light: no shadows.
  Vec3 fill_from{-1.5, -1.0, 0.5};
  double fill_intensity = 0.25;
  // Ambient light, shadowed by ambient occlusion within ao_distance.
  double ambient = 0.4;
  int ao_samples = 2;        // rays a camera sample sends; 0: no occlusion
  double ao_distance = 1.0;  // in the data's units (resolved from the glyphs)
  double specular = 0.25;    // Blinn–Phong highlight strength
  double shininess = 40.0;

  BackgroundKind background_kind = BackgroundKind::solid;
  Rgb background{1, 1, 1};         // solid, or the top of the gradient
  Rgb background_bottom{1, 1, 1};  // the gradient's bottom
  // A ground plane under the data that only catches the key light's
  // shadows: what is below the data is darkened by up to ground_shadow.
  bool ground = false;
  double ground_height = 0.0;  // z of the plane
  double ground_shadow = 0.5;

  Rgb box_color{0.05f, 0.05f, 0.05f};  // the domain's edges, when drawn
  Rgb trajectory_color{0.25f, 0.25f, 0.25f};  // trajectory tubes, when drawn
  // A data set's boundary surface, when drawn, is a translucent shell; its
  // opacity rises towards grazing angles, so the outline reads as an edge.
  Rgb shell_color{0.6f, 0.65f, 0.7f};
  double shell_opacity = 0.08;       // facing the viewer
  double shell_edge_opacity = 0.6;   // at grazing angles
};

// What the occlusion rays found at a surface point: the fraction of the
// key light's disc that is visible, and of the ambient hemisphere.
struct Visibility {
  double key = 1.0;
  double ambient = 1.0;
};

// Light leaving a glyph surface point towards the viewer. `to_viewer` is
// unit; the normal may face either way (the side the viewer sees is lit).
Rgb shade_surface(const ShadingSpec& spec, const Rgb& albedo, const Vec3& normal, const Vec3& to_viewer,
                  const Visibility& visibility);

// The side of a surface the viewer sees: the normal turned towards it.
inline Vec3 facing_normal(const Vec3& normal, const Vec3& to_viewer) {
  return normal.dot(to_viewer) < 0.0 ? Vec3(-normal) : normal;
}

// The background seen at picture height v ∈ [0, 1] (0 the top).
Rgb background_at(const ShadingSpec& spec, double v);

}  // namespace hsb
