#pragma once
// The colour bar: what a figure's colours mean. Its text is laid out by
// Pango and drawn by Cairo, so titles can say "λ₃ (MPa)" and labels use a
// true minus sign; ticks sit at round values (ticks.h). Sizes are in
// points at the picture's DPI, so the legend prints at the size journals
// ask for. The same layout is drawn into a raster picture (the bar's
// pixels set exactly: the colour at each tick is the colormap's, through
// the same colour path as the glyphs) and into a PDF or SVG page (the bar,
// ticks and text as vector shapes and text).

#include <cairo.h>

#include <string>
#include <vector>

#include "renderer/image/color_management.h"
#include "renderer/image/colormap.h"
#include "renderer/image/ticks.h"

namespace hsb {

enum class LegendPlacement { right, bottom };

struct LegendStyle {
  LegendPlacement placement = LegendPlacement::right;
  double font_size = 7.0;  // points
  double length = 0.6;     // of the picture's height (right) or width (bottom)
  double dpi = 300.0;
};

// Where everything goes, in the picture's pixels.
struct LegendLayout {
  LegendStyle style;
  // dpi/72, or less on a picture under 2.5 inches at its DPI: there the
  // legend scales with the picture.
  double pixels_per_point = 1.0;
  double bar_x0 = 0, bar_y0 = 0, bar_x1 = 0, bar_y1 = 0;  // the colour strip
  TickSet ticks;
  std::string title;
  // A clipped end's extension triangle (as matplotlib's `extend`) is
  // labelled with the values' true extreme: "max 312" ("" when that end
  // is not clipped).
  std::string low_label, high_label;
  // The part of the picture the legend takes, from its right (or bottom)
  // edge: the camera frames the data in the rest.
  double reserved = 0.0;  // a fraction of the width (right) or height (bottom)

  // Where along the bar a value lies, in pixels.
  double position(const ColorScale& scale, double value) const;
  // The same legend moved by (dx, dy) pixels (a panel's, into its figure).
  LegendLayout shifted(double dx, double dy) const;
};

// Pixels a point takes in a width × height picture at `dpi`: dpi/72, or
// less on a picture under 2.5 inches, where the legend (and a figure's
// labels) scale with the picture.
double legend_pixels_per_point(double dpi, int width, int height);

LegendLayout layout_legend(const ColorScale& scale, const std::string& title, const LegendStyle& style, int width,
                           int height);

// Onto display-referred, premultiplied RGBA pixels. `ink` is the text's
// and frame's grey (0 black, 1 white).
void draw_legend(std::vector<float>& rgba, int width, int height, const LegendLayout& layout,
                 const ColorScale& scale, const ColorManagement& color, float ink);

// Onto a Cairo context whose user space is the picture's pixels (a PDF or
// SVG page scaled from points), all as vector shapes and text.
void draw_legend(cairo_t* cr, const LegendLayout& layout, const ColorScale& scale, const ColorManagement& color,
                 float ink);

}  // namespace hsb
