#pragma once
// A labelled colour bar drawn onto a display-referred image, so a figure
// says what its colours mean.

#include <string>
#include <vector>

#include "renderer/image/color_management.h"
#include "renderer/image/colormap.h"

namespace hsb {

struct ColorbarSpec {
  std::string title;  // e.g. "λ3 (minor)"
};

// Draws a vertical bar with its title and end values at the right edge of
// `rgba` (display-referred, 4 channels). The bar's colours are the
// colormap's colours through the same path glyph colours take (to
// scene-linear, then the display transform), so bar and glyphs match under
// any OCIO config. Throws std::runtime_error when text cannot be drawn.
// The fraction of the picture's width, at its right, the bar and its labels
// take: kept free of the data when the camera frames it.
double colorbar_width_fraction(int width, int height);

void draw_colorbar(std::vector<float>& rgba, int width, int height, const ColorScale& scale,
                   const ColorbarSpec& spec, const ColorManagement& color);

}  // namespace hsb
