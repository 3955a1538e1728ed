#include "renderer/image/colorbar.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace hsb {
namespace {

std::string font_name() {
  // Debian's fonts-dejavu-core; OIIO also finds "DejaVuSans" by name, but
  // the full path avoids depending on its search list.
  const char* path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  return std::filesystem::exists(path) ? path : "DejaVuSans";
}

std::string format_value(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

struct BarLayout {
  int font, bar_w, margin;
  BarLayout(int width, int height)
      : font(std::max(10, height / 36)), bar_w(std::max(8, width / 36)), margin(std::max(6, width / 40)) {}
  // Labels such as "-1.05e+03": about seven characters at 0.6 em.
  int label_width() const { return int(7 * 0.6 * font) + font / 2; }
};

}  // namespace

double colorbar_width_fraction(int width, int height) {
  const BarLayout l(width, height);
  return double(l.margin + l.bar_w + l.label_width()) / double(width);
}

void draw_colorbar(std::vector<float>& rgba, int width, int height, const ColorScale& scale,
                   const ColorbarSpec& spec, const ColorManagement& color) {
  OIIO::ImageSpec image_spec(width, height, 4, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf image(image_spec, rgba.data());  // wraps the caller's pixels

  const BarLayout layout(width, height);
  const int font = layout.font, bar_w = layout.bar_w, margin = layout.margin;
  const int x1 = width - margin, x0 = x1 - bar_w;
  const int y0 = height / 6 + 2 * font, y1 = height - height / 6;
  if (x0 < 0 || y1 - y0 < 8) return;  // too small to say anything useful

  // The bar: one colour per row, top = high values.
  std::vector<float> strip(std::size_t(y1 - y0) * 4);
  for (int y = y0; y < y1; ++y) {
    const double u = 1.0 - (y - y0 + 0.5) / double(y1 - y0);
    const Rgb linear = color.to_scene_linear(scale.map->at(u));
    float* p = &strip[std::size_t(y - y0) * 4];
    p[0] = linear[0];
    p[1] = linear[1];
    p[2] = linear[2];
    p[3] = 1.0f;
  }
  color.apply_display(strip, 1, y1 - y0);
  for (int y = y0; y < y1; ++y) {
    const float* p = &strip[std::size_t(y - y0) * 4];
    OIIO::ImageBufAlgo::fill(image, {p, 4}, OIIO::ROI(x0, x1, y, y + 1, 0, 1, 0, 4));
  }

  // Text and frame in black or white, whichever stands out from the
  // background at the bar's left.
  const float* bg = &rgba[(std::size_t(y0) * width + std::max(0, x0 - 2 * font)) * 4];
  const float luminance = 0.2126f * bg[0] + 0.7152f * bg[1] + 0.0722f * bg[2];
  const float ink_value = luminance > 0.5f ? 0.0f : 1.0f;
  const float ink[4] = {ink_value, ink_value, ink_value, 1.0f};
  OIIO::ImageBufAlgo::render_box(image, x0 - 1, y0 - 1, x1, y1, {ink, 4});

  const std::string fontname = font_name();
  auto text = [&](int x, int y, const std::string& s, OIIO::ImageBufAlgo::TextAlignX ax,
                  OIIO::ImageBufAlgo::TextAlignY ay) {
    if (!OIIO::ImageBufAlgo::render_text(image, x, y, s, font, fontname, {ink, 4}, ax, ay))
      throw std::runtime_error("cannot draw the colour bar's text: " + image.geterror() +
                               " (is fonts-dejavu-core installed?)");
  };
  using AX = OIIO::ImageBufAlgo::TextAlignX;
  using AY = OIIO::ImageBufAlgo::TextAlignY;
  const int label_x = x0 - font / 2;
  text(label_x, y0, format_value(scale.hi), AX::Right, AY::Center);
  text(label_x, y1, format_value(scale.lo), AX::Right, AY::Center);
  if (scale.lo < 0.0 && scale.hi > 0.0) {
    const int y_zero = y0 + int(std::lround((1.0 - scale.normalized(0.0)) * (y1 - y0)));
    if (std::abs(y_zero - y0) > font && std::abs(y1 - y_zero) > font)
      text(label_x, y_zero, "0", AX::Right, AY::Center);
  }
  if (!spec.title.empty()) text(x1, y0 - font, spec.title, AX::Right, AY::Bottom);  // above the top label
}

}  // namespace hsb
