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
constexpr int kDefaultTicks = 5;   // about this many ticks on a bar
constexpr double kKeyGlyph = 9.0;  // a key glyph's longest half-axis
constexpr double kKeyRow = 14.0;   // a key row's height
constexpr double kTriad = 14.0;    // the direction key's radius
constexpr double kTitleWrap = 80.0;  // the direction key's title is wrapped at this width
// The smallest picture, in points, the legend keeps its printed size in:
// 2.5 inches. A smaller picture (a thumbnail, a golden image) is not a
// print; its legend shrinks with it, so that it never takes over the
// picture.
constexpr double kFullSizePicture = 180.0;

// An sRGB colour as the glyphs get it, display-referred: to scene-linear,
// then the display transform.
Rgb display_rgb(const ColorManagement& color, const Rgb& srgb) {
  std::vector<float> pixel(4, 1.0f);
  const Rgb linear = color.to_scene_linear(srgb);
  for (int c = 0; c < 3; ++c) pixel[std::size_t(c)] = linear[std::size_t(c)];
  color.apply_display(pixel, 1, 1);
  return {pixel[0], pixel[1], pixel[2]};
}

// The colour at bar fraction u ∈ [0, 1], display-referred.
Rgb display_color(const ColorScale& scale, const ColorManagement& color, double u) {
  return display_rgb(color, scale.map->at(u));
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

// How far the bar's end decorations reach beyond its ends, in pixels: an
// extension triangle (with its label, on the right) and, at the high end,
// the factor ("×10⁶") with a gap.
struct EndReach {
  double high = 0.0, low = 0.0, factor = 0.0;
};
EndReach end_reach(cairo_t* cr, const LegendLayout& l) {
  const double p = l.pixels_per_point, font = l.style.font_size * p;
  const bool right = l.style.placement == LegendPlacement::right;
  EndReach r;
  r.high = l.high_label.empty() ? 0.0 : kTriangle * p + (right ? font : 0.0);
  r.low = l.low_label.empty() ? 0.0 : kTriangle * p + (right ? font : 0.0);
  if (!l.ticks.factor.empty()) {
    double w, h;
    text_size(cr, l.ticks.factor, font, w, h);
    r.factor = (right ? h : w) + kGap * p;
  }
  return r;
}

// The words for what the bar's ends stand for: on the right above and
// below it, beyond its extension triangles and its factor; at the bottom
// under its ends, on the title's row (`title_y`).
void draw_end_words(cairo_t* cr, const LegendLayout& l, const EndReach& reach, double title_y) {
  const double p = l.pixels_per_point, font = l.style.font_size * p;
  if (l.style.placement == LegendPlacement::right) {
    if (!l.high_word.empty()) show_text(cr, l.high_word, font, l.bar_x0, l.bar_y0 - kGap * p - reach.high - reach.factor, 0.0, 1.0);
    if (!l.low_word.empty()) show_text(cr, l.low_word, font, l.bar_x0, l.bar_y1 + kGap * p + reach.low, 0.0, 0.0);
  } else {
    if (!l.high_word.empty()) show_text(cr, l.high_word, font, l.bar_x1, title_y, 1.0, 0.0);
    if (!l.low_word.empty()) show_text(cr, l.low_word, font, l.bar_x0, title_y, 0.0, 0.0);
  }
}

// The colour bar's ticks, labels, factor, title, frame, extension
// triangles and end words, with its strip already in place.
void draw_bar_annotations(cairo_t* cr, const LegendLayout& l, const ColorScale& scale, const ColorManagement& color,
                          float ink) {
  const double p = l.pixels_per_point, font = l.style.font_size * p;
  cairo_set_source_rgb(cr, ink, ink, ink);
  cairo_set_line_width(cr, kStroke * p);
  cairo_rectangle(cr, l.bar_x0, l.bar_y0, l.bar_x1 - l.bar_x0, l.bar_y1 - l.bar_y0);
  cairo_stroke(cr);
  draw_extension(cr, l, scale, color, ink, true);
  draw_extension(cr, l, scale, color, ink, false);
  // The factor clears a high end's triangle and label.
  const EndReach reach = end_reach(cr, l);
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
  double title_y = 0.0;
  if (right) {
    if (!l.ticks.factor.empty())
      show_text(cr, l.ticks.factor, font, l.bar_x0, l.bar_y0 - kGap * p - reach.high, 0.0, 1.0);
    const double x = l.bar_x1 + (kTickLength + 2.0 * kGap) * p + widest;
    show_text(cr, l.title, font, x, 0.5 * (l.bar_y0 + l.bar_y1), 0.5, 0.0, true, false, l.title_wrap);
  } else {
    if (!l.ticks.factor.empty())
      show_text(cr, l.ticks.factor, font, l.bar_x1 + kGap * p + reach.high, l.bar_y0, 0.0, 0.0);
    double w, h;
    text_size(cr, "0", font, w, h);
    title_y = l.bar_y1 + (kTickLength + 2.0 * kGap) * p + h;
    show_text(cr, l.title, font, 0.5 * (l.bar_x0 + l.bar_x1), title_y, 0.5, 0.0);
  }
  draw_end_words(cr, l, reach, title_y);
}

// The shape key's glyphs, each its outline filled with a grey lit from
// the upper left (a vector gradient) and stroked, and their labels, on a
// panel of the paper's shade: a view framed by hand may have glyphs where
// the key goes, and the key must read over them.
void draw_shape_key(cairo_t* cr, const LegendLayout& l, float ink) {
  if (l.key.empty()) return;
  const double p = l.pixels_per_point, font = l.style.font_size * p, g = l.key_glyph;
  const double pad = kGap * p, corner = 2.0 * kGap * p;
  const double x0 = l.key_x0 - pad, y0 = l.key_y0 - pad;
  const double x1 = l.key_x0 + l.key_width + pad, y1 = l.key_y0 + double(l.key.size()) * l.key_row + pad;
  cairo_new_path(cr);
  cairo_arc(cr, x1 - corner, y0 + corner, corner, -0.5 * M_PI, 0.0);
  cairo_arc(cr, x1 - corner, y1 - corner, corner, 0.0, 0.5 * M_PI);
  cairo_arc(cr, x0 + corner, y1 - corner, corner, 0.5 * M_PI, M_PI);
  cairo_arc(cr, x0 + corner, y0 + corner, corner, M_PI, 1.5 * M_PI);
  cairo_close_path(cr);
  const double paper = 1.0 - ink;
  cairo_set_source_rgba(cr, paper, paper, paper, 0.8);
  cairo_fill(cr);
  for (std::size_t i = 0; i < l.key.size(); ++i) {
    const ShapeKeyEntry& entry = l.key[i];
    const double cx = l.key_x0 + g, cy = l.key_y0 + (double(i) + 0.5) * l.key_row;
    cairo_new_path(cr);
    for (const auto& point : entry.outline) cairo_line_to(cr, cx + g * point[0], cy - g * point[1]);
    cairo_close_path(cr);
    const CairoOwned<cairo_pattern_t> light(
        cairo_pattern_create_radial(cx - 0.4 * g, cy - 0.3 * g, 0.0, cx - 0.2 * g, cy - 0.15 * g, 1.2 * g));
    cairo_pattern_add_color_stop_rgb(light.get(), 0.0, 0.92, 0.92, 0.92);
    cairo_pattern_add_color_stop_rgb(light.get(), 1.0, 0.45, 0.45, 0.45);
    cairo_set_source(cr, light.get());
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, ink, ink, ink);
    cairo_set_line_width(cr, kStroke * p);
    cairo_stroke(cr);
    show_text(cr, entry.label, font, cx + g + kGap * p, cy, 0.0, 0.5);
  }
}

// The direction key: each axis a line through the centre both ways (the
// colour has no sign) in the colour a glyph along it gets, its positive
// end labelled beyond it; the title under the triad.
void draw_direction_key(cairo_t* cr, const LegendLayout& l, const ColorManagement& color, float ink) {
  if (!l.direction) return;
  const double p = l.pixels_per_point, font = l.style.font_size * p, r = l.triad_r, gap = kGap * p;
  cairo_set_line_width(cr, 1.5 * p);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (int k = 0; k < 3; ++k) {
    const auto& a = l.direction->axes[std::size_t(k)];
    Vec3 axis = Vec3::Zero();
    axis[k] = 1.0;
    const Rgb c = display_rgb(color, direction_srgb(axis, 1.0));
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    cairo_move_to(cr, l.triad_x - r * a[0], l.triad_y + r * a[1]);
    cairo_line_to(cr, l.triad_x + r * a[0], l.triad_y - r * a[1]);
    cairo_stroke(cr);
  }
  cairo_set_source_rgb(cr, ink, ink, ink);
  for (int k = 0; k < 3; ++k) {
    const auto& a = l.direction->axes[std::size_t(k)];
    const double length = std::hypot(a[0], a[1]);
    // Beyond the positive end, anchored on the side that faces away.
    const double ux = length > 1e-6 ? a[0] / length : 0.0, uy = length > 1e-6 ? a[1] / length : 0.0;
    show_text(cr, l.direction->labels[std::size_t(k)], font, l.triad_x + (r * length + gap) * ux,
              l.triad_y - (r * length + gap) * uy, 0.5 - 0.5 * ux, 0.5 + 0.5 * uy);
  }
  show_text(cr, l.title, font, l.triad_x, l.triad_title_y, 0.5, 0.0, false, false, kTitleWrap * p);
}

// Everything but the bar's strip.
void draw_annotations(cairo_t* cr, const LegendLayout& l, const ColorScale& scale, const ColorManagement& color,
                      float ink) {
  if (l.bar) draw_bar_annotations(cr, l, scale, color, ink);
  draw_direction_key(cr, l, color, ink);
  draw_shape_key(cr, l, ink);
}

// The bar's ticks, about `target` of them, and the labels of its clipped
// ends in their unit.
void set_ticks(LegendLayout& l, const ColorScale& scale, int target) {
  l.ticks = scale.log         ? log_ticks(scale.lo, scale.hi)
            : scale.two_sided() ? two_sided_ticks(scale.lo, scale.hi, target)
                                : linear_ticks(scale.lo, scale.hi, target);
  const int exponent = scale.log ? 0 : l.ticks.exponent;
  if (scale.clipped_high()) l.high_label = "max " + value_label(scale.data_hi, exponent);
  if (scale.clipped_low()) l.low_label = "min " + value_label(scale.data_lo, exponent);
}

// Whether each tick's label clears its neighbours' along the bar.
bool tick_labels_fit(cairo_t* cr, const LegendLayout& l, const ColorScale& scale) {
  const double font = l.style.font_size * l.pixels_per_point, gap = kGap * l.pixels_per_point;
  const bool right = l.style.placement == LegendPlacement::right;
  double previous_at = 0.0, previous_half = 0.0;
  for (std::size_t i = 0; i < l.ticks.ticks.size(); ++i) {
    double w, h;
    text_size(cr, l.ticks.ticks[i].label, font, w, h);
    const double at = l.position(scale, l.ticks.ticks[i].value), half = 0.5 * (right ? h : w + gap);
    if (i > 0 && std::fabs(at - previous_at) < previous_half + half) return false;
    previous_at = at, previous_half = half;
  }
  return true;
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
  moved.key_x0 += dx, moved.key_y0 += dy;
  moved.triad_x += dx, moved.triad_y += dy, moved.triad_title_y += dy;
  moved.left += dx, moved.top += dy;
  return moved;
}

std::array<double, 2> LegendLayout::ink_sample() const {
  if (bar) return {bar_x0 - 2.0, bar_y0};
  if (direction) return {left - 2.0, triad_y};
  return {key_x0 - 2.0, key_y0};
}

LegendLayout layout_legend(const ColorScale& scale, const LegendContent& content, const LegendStyle& style, int width,
                           int height) {
  LegendLayout l;
  l.style = style;
  l.bar = content.bar;
  l.title = content.title;
  l.low_word = content.low_word, l.high_word = content.high_word;
  l.key = content.key;
  l.direction = content.direction;
  if (l.direction && l.bar) throw std::logic_error("a legend has a colour bar or a direction key, not both");
  l.pixels_per_point = legend_pixels_per_point(style.dpi, width, height);
  const double p = l.pixels_per_point, font = style.font_size * p, margin = kMargin * p, gap = kGap * p;
  const bool right = style.placement == LegendPlacement::right;
  const CairoOwned<cairo_t> cr = measuring_context();
  const auto measure = [&](const std::string& text, double& w, double& h) {
    double tw, th;
    text_size(cr.get(), text, font, tw, th);
    w = std::max(w, tw), h = std::max(h, th);
  };

  // The shape key: a column of rows, each a glyph and its label.
  double key_w = 0.0, key_h = 0.0;
  if (!l.key.empty()) {
    double label_w = 0.0, label_h = 0.0;
    for (const ShapeKeyEntry& entry : l.key) measure(entry.label, label_w, label_h);
    l.key_glyph = kKeyGlyph * p;
    l.key_row = std::max(kKeyRow * p, label_h + gap);
    key_w = l.key_width = 2.0 * l.key_glyph + gap + label_w;
    key_h = double(l.key.size()) * l.key_row;
  }

  // The bar's block: its strip, ticks, labels and title across; words at
  // its ends.
  double bar_across = 0.0, words_w = 0.0, words_h = 0.0, title_w = 0.0, title_h = 0.0, title_row = 0.0;
  if (l.bar) {
    set_ticks(l, scale, kDefaultTicks);
    double label_w = 0.0, label_h = 0.0;
    for (const Tick& t : l.ticks.ticks) measure(t.label, label_w, label_h);
    for (const std::string& extreme : {l.low_label, l.high_label}) measure(extreme, label_w, label_h);
    measure(l.title.empty() ? " " : l.title, title_w, title_h);
    // On the right the words stand above and below the bar (the widest
    // must fit the column); at the bottom they share the title's row.
    double both_w = 0.0;
    for (const std::string& word : {l.low_word, l.high_word}) {
      double w = 0.0;
      if (!word.empty()) measure(word, w, words_h);
      words_w = std::max(words_w, w), both_w += w;
    }
    title_row = (l.title.empty() ? 0.0 : title_w) + both_w + (both_w > 0.0 ? 4.0 * gap : 0.0);
    bar_across = (kBarWidth + kTickLength + 2.0 * kGap + kMargin) * p + (right ? label_w : label_h) + title_h;
  }
  const EndReach reach = l.bar ? end_reach(cr.get(), l) : EndReach{};

  // The direction key: the triad with its labels round it, the title
  // (wrapped) under it.
  double triad_w = 0.0, triad_h = 0.0, triad_above = 0.0;  // its block, and its centre's depth in it
  if (l.direction) {
    l.triad_r = kTriad * p;
    double label_w = 0.0, label_h = 0.0;
    for (const std::string& label : l.direction->labels) measure(label, label_w, label_h);
    double wrapped_w = 0.0, wrapped_h = 0.0;
    if (!l.title.empty()) text_size(cr.get(), l.title, font, wrapped_w, wrapped_h, false, kTitleWrap * p);
    triad_w = std::max(2.0 * (l.triad_r + gap + label_w), wrapped_w);
    triad_above = l.triad_r + gap + label_h;
    triad_h = 2.0 * triad_above + (l.title.empty() ? 0.0 : wrapped_h + gap);
  }

  if (right) {
    const double words = words_h > 0.0 ? words_h + gap : 0.0;
    const double above = gap + reach.high + reach.factor + words, below = gap + reach.low + words;
    // The bar, its ends' decorations and the key under them are centred
    // as one group; the bar is lengthened up to its title's length, and
    // shortened where they would not fit.
    const double key_part = l.key.empty() ? 0.0 : key_h + (l.bar || l.direction ? 2.0 * gap : 0.0);
    const double room = height - 2.0 * (std::max(above, below) + margin) - key_part;
    const double length = l.bar ? std::max(0.0, std::min(std::max(style.length * height, title_w), room)) : 0.0;
    // A title still longer than the bar is wrapped at its length: its
    // lines stand side by side, so the column widens by the extra ones.
    if (l.bar && !l.title.empty() && title_w > length && length > 0.0) {
      l.title_wrap = length;
      double wrapped_w = 0.0, wrapped_h = 0.0;
      text_size(cr.get(), l.title, font, wrapped_w, wrapped_h, false, length);
      bar_across += wrapped_h - title_h;
    }
    // One column at the picture's right edge: the bar, and the key at its
    // foot; the words above and below the bar must fit in it too.
    const double block = std::max({bar_across, key_w + margin, words_w > 0.0 ? words_w + margin : 0.0,
                                   triad_w > 0.0 ? triad_w + margin : 0.0});
    l.left = width - block;
    l.key_x0 = l.bar_x0 = l.left;
    l.bar_x1 = l.bar_x0 + kBarWidth * p;
    const double group = (l.bar ? above + length + below : 0.0) + triad_h + key_part;
    // Without a key the bar alone is centred on the picture, as it always was.
    l.bar_y0 = l.key.empty() ? 0.5 * (height - length) : 0.5 * (height - group) + (l.bar ? above : 0.0);
    l.bar_y1 = l.bar_y0 + length;
    l.key_y0 = 0.5 * (height - group) + group - key_h;
    l.triad_x = l.left + 0.5 * triad_w;
    l.triad_y = 0.5 * (height - group) + triad_above;
    l.top = 0.0;
    l.reserved = (block + margin) / width;
  } else {
    // One band along the picture's foot: the bar centred in it, the key
    // at its right end; the words at the bar's ends must fit beside it.
    const double band = std::max({bar_across, key_h > 0.0 ? key_h + margin + gap : 0.0,
                                  triad_h > 0.0 ? triad_h + margin : 0.0});
    l.top = height - band;
    l.bar_y0 = height - bar_across;
    l.bar_y1 = l.bar_y0 + kBarWidth * p;
    l.key_x0 = width - margin - key_w;
    l.key_y0 = height - margin - key_h;
    // The bar is long enough for its title row (the end words and the
    // title between them), as far as the width the key leaves it allows.
    const double before = gap + reach.low, after = gap + reach.high + reach.factor;
    const double free_width = l.key.empty() ? width : l.key_x0 - 2.0 * gap;
    const double length = std::max(0.0, std::min(std::max(style.length * width, title_row),
                                                 free_width - 2.0 * (std::max(before, after) + margin)));
    l.bar_x0 = 0.5 * (free_width - length);
    l.bar_x1 = l.bar_x0 + length;
    l.triad_x = 0.5 * free_width;
    l.triad_y = height - margin - triad_h + triad_above;
    l.left = 0.0;
    l.reserved = (band + margin) / height;
  }
  l.triad_title_y = l.triad_y + triad_above;
  // Fewer ticks where the bar is too short for their labels.
  for (int target = kDefaultTicks - 1; l.bar && !scale.log && target >= 2 && !tick_labels_fit(cr.get(), l, scale); --target)
    set_ticks(l, scale, target);
  return l;
}

namespace {

// The strip, pixel by pixel: each pixel's colour is the colormap's at
// the value its centre stands for.
void fill_strip(std::vector<float>& rgba, int width, int height, const LegendLayout& l, const ColorScale& scale,
                const ColorManagement& color) {
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
}

// The strip as thin rectangles, one per 1/512 of the scale: vector
// shapes, each the colormap's colour at its middle.
void fill_strip(cairo_t* cr, const LegendLayout& l, const ColorScale& scale, const ColorManagement& color) {
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
}

}  // namespace

void draw_legend(std::vector<float>& rgba, int width, int height, const LegendLayout& l, const ColorScale& scale,
                 const ColorManagement& color, float ink) {
  if (l.bar) fill_strip(rgba, width, height, l, scale, color);

  // The rest through Cairo, on a transparent layer over the legend's part
  // of the picture, composited over it.
  const int left = std::max(0, int(std::floor(l.left - 2.0 * l.pixels_per_point)));
  const int top = std::max(0, int(std::floor(l.top - 2.0 * l.pixels_per_point)));
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
  if (l.bar) fill_strip(cr, l, scale, color);
  draw_annotations(cr, l, scale, color, ink);
}

}  // namespace hsb
