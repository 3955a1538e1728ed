#pragma once
// What is drawn over a rendered picture before it becomes a file: colour
// bars and text (a figure's panel labels and caption). The same
// annotations go onto a raster picture (PNG, TIFF) and, as vector shapes
// and text, onto a PDF or SVG page.

#include <cairo.h>

#include <string>
#include <vector>

#include "renderer/image/color_management.h"
#include "renderer/image/colormap.h"
#include "renderer/image/legend.h"

namespace hsb {

struct PlacedLegend {
  LegendLayout layout;  // in the picture's pixels
  ColorScale scale;
  float ink = 0.0f;  // the text's and frame's grey (0 black, 1 white)
};

struct FigureText {
  std::string text;
  double x = 0, y = 0;                // in the picture's pixels
  double size_px = 12;
  double anchor_x = 0, anchor_y = 0;  // 0 left/top to 1 right/bottom of the text
  bool bold = false;
  double wrap_px = 0;                 // > 0: wrapped to this width, centred
  float ink = 0.0f;
};

struct Annotations {
  std::vector<PlacedLegend> legends;
  std::vector<FigureText> texts;
};

// Onto display-referred, premultiplied RGBA pixels.
void draw_annotations(std::vector<float>& rgba, int width, int height, const Annotations& annotations,
                      const ColorManagement& color);
// Onto a Cairo context whose user space is the picture's pixels.
void draw_annotations(cairo_t* cr, const Annotations& annotations, const ColorManagement& color);

}  // namespace hsb
