#include "renderer/image/legend.h"

#include "renderer/image/text.h"


#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace hsb {
namespace {

// Gaps and strokes, in points.
constexpr double kBarWidth = 9.0;
constexpr double kTickLength = 2.5;
constexpr double kGap = 2.5;
constexpr double kMargin = 6.0;
constexpr double kStroke = 0.5;
constexpr double kTriangle = 7.0;  // an extension triangle's length
// The smallest picture, in points, the legend keeps its printed size in:
// 2.5 inches. A smaller picture (a thumbnail, a golden image) is not a
// print; its legend shrinks with it, so that it never takes over the
// picture.
constexpr double kFullSizePicture = 180.0;

// The colour at bar fraction u ∈ [0, 1], display-referred, as the glyphs
// get it: the colormap's sRGB to scene-linear, then the display transform.
Rgb display_color(const ColorScale& scale, const ColorManagement& color, double u) {
  std::vector<float> pixel(4, 1.0f);
  const Rgb linear = color.to_scene_linear(scale.map->at(u));
  for (int c = 0; c < 3; ++c) pixel[std::size_t(c)] = linear[std::size_t(c)];
  color.apply_display(pixel, 1, 1);
  return {pixel[0], pixel[1], pixel[2]};
}

// The extension triangle at the bar's high (or low) end, filled with that
// end's colour and outlined, and its label: the values' true extreme.
void draw_extension(cairo_t* cr, const LegendLayout& l, const ColorScale& scale, const ColorManagement& color,
                    float ink, bool high) {
  const std::string& label = high ? l.high_label : l.low_label;
  if (label.empty()) return;
  const double p = l.pixels_per_point, font = l.style.font_size * p, tri = kTriangle * p;
  const bool right = l.style.placement == LegendPlacement::right;
  double ax, ay, bx, by, tx, ty;  // the base's ends, the tip
  if (right) {
    const double y = high ? l.bar_y0 : l.bar_y1, out = high ? -tri : tri;
    ax = l.bar_x0, bx = l.bar_x1, ay = by = y, tx = 0.5 * (l.bar_x0 + l.bar_x1), ty = y + out;
  } else {
    const double x = high ? l.bar_x1 : l.bar_x0, out = high ? tri : -tri;
    ay = l.bar_y0, by = l.bar_y1, ax = bx = x, ty = 0.5 * (l.bar_y0 + l.bar_y1), tx = x + out;
  }
  const Rgb c = display_color(scale, color, high ? 1.0 : 0.0);
  cairo_move_to(cr, ax, ay);
  cairo_line_to(cr, bx, by);
  cairo_line_to(cr, tx, ty);
  cairo_close_path(cr);
  cairo_set_source_rgb(cr, c[0], c[1], c[2]);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, ink, ink, ink);
  cairo_stroke(cr);
  if (right)
    show_text(cr, label, font, l.bar_x1 + (kTickLength + kGap) * p, ty + (high ? -0.3 : 0.3) * font, 0.0, 0.5);
  else
    show_text(cr, label, font, tx, l.bar_y1 + (kTickLength + kGap) * p, high ? 0.0 : 1.0, 0.0);
}

// Ticks, labels, factor, title, frame and extension triangles, with the
// bar already in place.
void draw_annotations(cairo_t* cr, const LegendLayout& l, const ColorScale& scale, const ColorManagement& color,
                      float ink) {
  const double p = l.pixels_per_point, font = l.style.font_size * p;
  cairo_set_source_rgb(cr, ink, ink, ink);
  cairo_set_line_width(cr, kStroke * p);
  cairo_rectangle(cr, l.bar_x0, l.bar_y0, l.bar_x1 - l.bar_x0, l.bar_y1 - l.bar_y0);
  cairo_stroke(cr);
  draw_extension(cr, l, scale, color, ink, true);
  draw_extension(cr, l, scale, color, ink, false);
  // The factor clears a high end's triangle and label.
  const double past_high = l.high_label.empty() ? 0.0 : kTriangle * p + (l.style.placement == LegendPlacement::right ? font : 0.0);
  const bool right = l.style.placement == LegendPlacement::right;
  double widest = 0.0;
  for (const Tick& t : l.ticks.ticks) {
    const double at = l.position(scale, t.value);
    if (right) {
      cairo_move_to(cr, l.bar_x1, at);
      cairo_line_to(cr, l.bar_x1 + kTickLength * p, at);
      cairo_stroke(cr);
      show_text(cr, t.label, font, l.bar_x1 + (kTickLength + kGap) * p, at, 0.0, 0.5);
      double w, h;
      text_size(cr, t.label, font, w, h);
      widest = std::max(widest, w);
    } else {
      cairo_move_to(cr, at, l.bar_y1);
      cairo_line_to(cr, at, l.bar_y1 + kTickLength * p);
      cairo_stroke(cr);
      show_text(cr, t.label, font, at, l.bar_y1 + (kTickLength + kGap) * p, 0.5, 0.0);
    }
  }
  if (right) {
    if (!l.ticks.factor.empty())
      show_text(cr, l.ticks.factor, font, l.bar_x0, l.bar_y0 - kGap * p - past_high, 0.0, 1.0);
    const double x = l.bar_x1 + (kTickLength + 2.0 * kGap) * p + widest;
    show_text(cr, l.title, font, x, 0.5 * (l.bar_y0 + l.bar_y1), 0.5, 0.0, true);
  } else {
    if (!l.ticks.factor.empty())
      show_text(cr, l.ticks.factor, font, l.bar_x1 + kGap * p + past_high, l.bar_y0, 0.0, 0.0);
    double w, h;
    text_size(cr, "0", font, w, h);
    show_text(cr, l.title, font, 0.5 * (l.bar_x0 + l.bar_x1), l.bar_y1 + (kTickLength + 2.0 * kGap) * p + h, 0.5,
              0.0);
  }
}

}  // namespace

double LegendLayout::position(const ColorScale& scale, double value) const {
  const double u = std::clamp(scale.normalized(value), 0.0, 1.0);
  return style.placement == LegendPlacement::right ? bar_y1 - u * (bar_y1 - bar_y0) : bar_x0 + u * (bar_x1 - bar_x0);
}

double legend_pixels_per_point(double dpi, int width, int height) {
  return std::min(dpi / 72.0, std::min(width, height) / kFullSizePicture);
}

LegendLayout LegendLayout::shifted(double dx, double dy) const {
  LegendLayout moved = *this;
  moved.bar_x0 += dx, moved.bar_x1 += dx;
  moved.bar_y0 += dy, moved.bar_y1 += dy;
  return moved;
}

LegendLayout layout_legend(const ColorScale& scale, const std::string& title, const LegendStyle& style, int width,
                           int height) {
  LegendLayout l;
  l.style = style;
  l.title = title;
  l.pixels_per_point = legend_pixels_per_point(style.dpi, width, height);
  const double p = l.pixels_per_point, font = style.font_size * p;
  l.ticks = scale.log ? log_ticks(scale.lo, scale.hi) : linear_ticks(scale.lo, scale.hi);
  const int exponent = scale.log ? 0 : l.ticks.exponent;
  if (scale.clipped_high()) l.high_label = "max " + value_label(scale.data_hi, exponent);
  if (scale.clipped_low()) l.low_label = "min " + value_label(scale.data_lo, exponent);
  const CairoOwned<cairo_t> cr = measuring_context();
  double label_w = 0.0, label_h = 0.0, title_w = 0.0, title_h = 0.0;
  for (const Tick& t : l.ticks.ticks) {
    double w, h;
    text_size(cr.get(), t.label, font, w, h);
    label_w = std::max(label_w, w), label_h = std::max(label_h, h);
  }
  for (const std::string& extreme : {l.low_label, l.high_label}) {
    double w, h;
    text_size(cr.get(), extreme, font, w, h);
    label_w = std::max(label_w, w), label_h = std::max(label_h, h);
  }
  text_size(cr.get(), title.empty() ? " " : title, font, title_w, title_h);
  if (style.placement == LegendPlacement::right) {
    const double block = (kBarWidth + kTickLength + 2.0 * kGap + kMargin) * p + label_w + title_h;
    l.bar_x0 = width - block + 0.0;
    l.bar_x1 = l.bar_x0 + kBarWidth * p;
    const double length = style.length * height;
    l.bar_y0 = 0.5 * (height - length);
    l.bar_y1 = l.bar_y0 + length;
    l.reserved = (block + kMargin * p) / width;
  } else {
    const double block = (kBarWidth + kTickLength + 2.0 * kGap + kMargin) * p + label_h + title_h;
    l.bar_y0 = height - block;
    l.bar_y1 = l.bar_y0 + kBarWidth * p;
    const double length = style.length * width;
    l.bar_x0 = 0.5 * (width - length);
    l.bar_x1 = l.bar_x0 + length;
    l.reserved = (block + kMargin * p) / height;
  }
  return l;
}

void draw_legend(std::vector<float>& rgba, int width, int height, const LegendLayout& l, const ColorScale& scale,
                 const ColorManagement& color, float ink) {
  // The strip, pixel by pixel: each pixel's colour is the colormap's at
  // the value its centre stands for.
  const bool right = l.style.placement == LegendPlacement::right;
  const int x0 = std::max(0, int(std::lround(l.bar_x0))), x1 = std::min(width, int(std::lround(l.bar_x1)));
  const int y0 = std::max(0, int(std::lround(l.bar_y0))), y1 = std::min(height, int(std::lround(l.bar_y1)));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const double u = right ? (l.bar_y1 - (y + 0.5)) / (l.bar_y1 - l.bar_y0) : (x + 0.5 - l.bar_x0) / (l.bar_x1 - l.bar_x0);
      const Rgb c = display_color(scale, color, std::clamp(u, 0.0, 1.0));
      float* p = &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
      p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 1.0f;
    }

  // The rest through Cairo, on a transparent layer over the legend's part
  // of the picture, composited over it.
  const int left = right ? std::max(0, int(std::floor(l.bar_x0 - 2.0 * l.pixels_per_point))) : 0;
  const int top = right ? 0 : std::max(0, int(std::floor(l.bar_y0 - 2.0 * l.pixels_per_point)));
  const int w = width - left, h = height - top;
  if (w <= 0 || h <= 0) return;
  CairoOwned<cairo_surface_t> surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h));
  {
    const CairoOwned<cairo_t> cr(cairo_create(surface.get()));
    cairo_translate(cr.get(), -left, -top);
    draw_annotations(cr.get(), l, scale, color, ink);
  }
  composite_layer(surface.get(), left, top, rgba, width, height);
}

void draw_legend(cairo_t* cr, const LegendLayout& l, const ColorScale& scale, const ColorManagement& color,
                 float ink) {
  // The strip as thin rectangles, one per 1/512 of the scale: vector
  // shapes, each the colormap's colour at its middle.
  constexpr int kSteps = 512;
  const bool right = l.style.placement == LegendPlacement::right;
  for (int i = 0; i < kSteps; ++i) {
    const double u = (i + 0.5) / kSteps;
    const Rgb c = display_color(scale, color, u);
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    if (right) {
      const double len = l.bar_y1 - l.bar_y0;
      cairo_rectangle(cr, l.bar_x0, l.bar_y1 - (i + 1) * len / kSteps, l.bar_x1 - l.bar_x0, len / kSteps + 0.05);
    } else {
      const double len = l.bar_x1 - l.bar_x0;
      cairo_rectangle(cr, l.bar_x0 + i * len / kSteps, l.bar_y0, len / kSteps + 0.05, l.bar_y1 - l.bar_y0);
    }
    cairo_fill(cr);
  }
  draw_annotations(cr, l, scale, color, ink);
}

}  // namespace hsb
