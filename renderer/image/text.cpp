#include "renderer/image/text.h"

#include <pango/pangocairo.h>

#include <cmath>
#include <cstdint>

namespace hsb {
namespace {

struct PangoDeleter {
  void operator()(PangoLayout* l) const { g_object_unref(l); }
  void operator()(PangoFontDescription* f) const { pango_font_description_free(f); }
};
template <class T>
using PangoOwned = std::unique_ptr<T, PangoDeleter>;

PangoOwned<PangoLayout> text_layout(cairo_t* cr, const std::string& text, double size_px, bool bold,
                                    double wrap_px) {
  PangoOwned<PangoLayout> layout(pango_cairo_create_layout(cr));
  PangoOwned<PangoFontDescription> font(pango_font_description_from_string("DejaVu Sans"));
  pango_font_description_set_absolute_size(font.get(), size_px * PANGO_SCALE);
  if (bold) pango_font_description_set_weight(font.get(), PANGO_WEIGHT_BOLD);
  pango_layout_set_font_description(layout.get(), font.get());
  if (wrap_px > 0.0) {
    pango_layout_set_width(layout.get(), int(wrap_px * PANGO_SCALE));
    pango_layout_set_wrap(layout.get(), PANGO_WRAP_WORD);
    pango_layout_set_alignment(layout.get(), PANGO_ALIGN_CENTER);
  }
  pango_layout_set_text(layout.get(), text.c_str(), -1);
  return layout;
}

}  // namespace

CairoOwned<cairo_t> measuring_context() {
  CairoOwned<cairo_surface_t> surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1));
  return CairoOwned<cairo_t>(cairo_create(surface.get()));
}

void text_size(cairo_t* cr, const std::string& text, double size_px, double& width, double& height, bool bold,
               double wrap_px) {
  const PangoOwned<PangoLayout> layout = text_layout(cr, text, size_px, bold, wrap_px);
  int w = 0, h = 0;
  pango_layout_get_size(layout.get(), &w, &h);
  width = double(w) / PANGO_SCALE;
  height = double(h) / PANGO_SCALE;
}

void show_text(cairo_t* cr, const std::string& text, double size_px, double x, double y, double ax, double ay,
               bool upright, bool bold, double wrap_px) {
  const PangoOwned<PangoLayout> layout = text_layout(cr, text, size_px, bold, wrap_px);
  int pw = 0, ph = 0;
  pango_layout_get_size(layout.get(), &pw, &ph);
  const double w = wrap_px > 0.0 ? wrap_px : double(pw) / PANGO_SCALE, h = double(ph) / PANGO_SCALE;
  cairo_save(cr);
  cairo_translate(cr, x, y);
  if (upright) cairo_rotate(cr, -M_PI / 2.0);
  cairo_move_to(cr, -ax * w, -ay * h);
  pango_cairo_show_layout(cr, layout.get());
  cairo_restore(cr);
}

void composite_layer(cairo_surface_t* layer, int left, int top, std::vector<float>& rgba, int width, int height) {
  cairo_surface_flush(layer);
  const unsigned char* data = cairo_image_surface_get_data(layer);
  const int stride = cairo_image_surface_get_stride(layer);
  const int w = cairo_image_surface_get_width(layer), h = cairo_image_surface_get_height(layer);
  for (int y = 0; y < h; ++y) {
    if (y + top < 0 || y + top >= height) continue;
    for (int x = 0; x < w; ++x) {
      if (x + left < 0 || x + left >= width) continue;
      // Cairo's ARGB32: premultiplied, native-endian 32-bit words.
      const std::uint32_t word = *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x);
      const float a = float((word >> 24) & 0xff) / 255.0f;
      if (a == 0.0f) continue;
      const float src[3] = {float((word >> 16) & 0xff) / 255.0f, float((word >> 8) & 0xff) / 255.0f,
                            float(word & 0xff) / 255.0f};
      float* p = &rgba[(std::size_t(y + top) * std::size_t(width) + std::size_t(x + left)) * 4];
      for (int c = 0; c < 3; ++c) p[c] = src[c] + (1.0f - a) * p[c];
      p[3] = a + (1.0f - a) * p[3];
    }
  }
}

}  // namespace hsb
