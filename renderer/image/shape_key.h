#pragma once
// The shape key: what a signed glyph's form says, shown beside the colour
// bar as sample glyphs labelled with what they stand for. Each sample is
// the outline of the very glyph the renderer draws (glyph_shape.h), seen
// along its third axis: the signed gauge is monotone in |q_z| on every
// branch, so that silhouette is exactly the shape's slice z = 0, a closed
// curve drawn as a vector path in PDF and SVG.

#include <array>
#include <string>
#include <vector>

namespace hsb {

struct ShapeKeyEntry {
  std::string label;  // "tension", "compression", "shear"
  // The outline, counter-clockwise, in units of the glyph's longest
  // half-axis: x along it (in [−1, 1]), y across it, y up.
  std::vector<std::array<double, 2>> outline;
};

// Three samples of the signed glyph at `sharpness`, each its long axis
// horizontal: tension along every axis (flat or round ends, no point),
// compression along every axis (a point at every end), and shear (pulled
// along its length, flat ends; pushed across it, points). The samples are
// physical states, so they are the same whichever sign the data calls
// positive.
std::vector<ShapeKeyEntry> signed_shape_key(double sharpness);

}  // namespace hsb
