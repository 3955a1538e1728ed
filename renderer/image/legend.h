#pragma once
// The legend: what a figure's colours mean (the colour bar) and, where the
// glyphs' forms carry meaning, what their shapes mean (the shape key,
// shape_key.h, under or beside the bar). Its text is laid out by
// Pango and drawn by Cairo, so titles can say "λ₃ (MPa)" and labels use a
// true minus sign; ticks sit at round values (ticks.h). Sizes are in
// points at the picture's DPI, so the legend prints at the size journals
// ask for. The same layout is drawn into a raster picture (the bar's
// pixels set exactly: the colour at each tick is the colormap's, through
// the same colour path as the glyphs) and into a PDF or SVG page (the bar,
// ticks and text as vector shapes and text).

#include <cairo.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "renderer/image/color_management.h"
#include "renderer/image/colormap.h"
#include "renderer/image/direction_key.h"
#include "renderer/image/shape_key.h"
#include "renderer/image/ticks.h"

namespace hsb {

enum class LegendPlacement { right, bottom };

struct LegendStyle {
  LegendPlacement placement = LegendPlacement::right;
  double font_size = 7.0;  // points
  double length = 0.6;     // of the picture's height (right) or width (bottom)
  double dpi = 300.0;
};

// What a legend shows.
struct LegendContent {
  bool bar = true;  // the scale's colour bar; false: the shape key alone
  std::string title;
  // What the bar's ends stand for, written beyond them ("compression" at
  // the low end and "tension" at the high end of signed stress); "" for
  // none.
  std::string low_word, high_word;
  // Sample glyphs with what their forms mean: under the bar on the right,
  // beside it at the bottom.
  std::vector<ShapeKeyEntry> key;
  // Direction colour's key, the title under it, instead of the bar (which
  // must then be off).
  std::optional<DirectionKey> direction;
};

// Where everything goes, in the picture's pixels.
struct LegendLayout {
  LegendStyle style;
  bool bar = true;
  // dpi/72, or less on a picture under 2.5 inches at its DPI: there the
  // legend scales with the picture.
  double pixels_per_point = 1.0;
  double bar_x0 = 0, bar_y0 = 0, bar_x1 = 0, bar_y1 = 0;  // the colour strip
  TickSet ticks;
  std::string title;
  // On the right, a title longer than the bar is wrapped at its length
  // (its lines side by side, each centred on the bar); 0 when it fits.
  double title_wrap = 0.0;
  // A clipped end's extension triangle (as matplotlib's `extend`) is
  // labelled with the values' true extreme: "max 312" ("" when that end
  // is not clipped).
  std::string low_label, high_label;
  std::string low_word, high_word;
  // The shape key: its rows' glyphs and labels from (key_x0, key_y0), its
  // top left, key_width across; a glyph's longest half-axis is key_glyph
  // pixels, a row key_row high.
  std::vector<ShapeKeyEntry> key;
  double key_x0 = 0, key_y0 = 0, key_width = 0, key_glyph = 0, key_row = 0;
  // The direction key: its triad's centre and an axis' half length seen
  // across the view (its radius); the title's top, centred under it.
  std::optional<DirectionKey> direction;
  double triad_x = 0, triad_y = 0, triad_r = 0, triad_title_y = 0;
  // The top left of all the legend draws.
  double left = 0, top = 0;
  // The part of the picture the legend takes, from its right (or bottom)
  // edge: the camera frames the data in the rest.
  double reserved = 0.0;  // a fraction of the width (right) or height (bottom)

  // Where along the bar a value lies, in pixels.
  double position(const ColorScale& scale, double value) const;
  // The same legend moved by (dx, dy) pixels (a panel's, into its figure).
  LegendLayout shifted(double dx, double dy) const;
  // The picture's pixel whose shade chooses the text's ink: just left of
  // the bar's top, or of the key's.
  std::array<double, 2> ink_sample() const;
};

// Pixels a point takes in a width × height picture at `dpi`: dpi/72, or
// less on a picture under 2.5 inches, where the legend (and a figure's
// labels) scale with the picture.
double legend_pixels_per_point(double dpi, int width, int height);

LegendLayout layout_legend(const ColorScale& scale, const LegendContent& content, const LegendStyle& style, int width,
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
