#pragma once
// Direction colour, the diffusion community's standard encoding of which
// way a fibre runs (Pajevic and Pierpaoli 1999): the principal
// eigenvector's components by magnitude as red, green and blue, weighted
// by the anisotropy, so that x runs red, y green, z blue, a diagonal mixes
// them, and an isotropic spot has no hue. The weight fades the colour to a
// middle grey rather than to black (as Teem's glyphs fade their
// saturation): a shaded glyph must keep its light and shade to show its
// form, and a dark one loses them. The colour has no sign, as an
// eigenvector has none.
//
// Its key replaces the colour bar: an axis triad as the camera sees the
// data's axes, each a line through the centre both ways in its own colour,
// its positive end labelled, drawn as vector lines and text in PDF and SVG.

#include <array>
#include <string>

#include "base/rgb.h"
#include "base/vec3.h"

namespace hsb {

// sRGB (|e_x|, |e_y|, |e_z|) for a unit direction e, mixed with grey by a
// weight in [0, 1] (FA; 1 for the bare direction, 0 for grey alone).
Rgb direction_srgb(const Vec3& direction, double weight);

struct DirectionKey {
  // Each world axis's unit vector as the camera sees it: its components
  // along the picture's right and up, each in [−1, 1].
  std::array<std::array<double, 2>, 3> axes{};
  // Each axis' positive end: "x", "y", "z", or the anatomical direction it
  // points to ("R", "A", "S").
  std::array<std::string, 3> labels{"x", "y", "z"};
};

// The key for a view whose picture's right and up are `right` and `up`
// (unit, world coordinates), its ends named by `anatomical_frame` where
// the data has one ("RAS": x to the right, y anterior, z superior).
DirectionKey direction_key(const Vec3& right, const Vec3& up, const std::string& anatomical_frame = "");

}  // namespace hsb
