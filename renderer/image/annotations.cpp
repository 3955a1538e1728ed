#include "renderer/image/annotations.h"

#include "renderer/image/text.h"

namespace hsb {
namespace {

void draw_texts(cairo_t* cr, const std::vector<FigureText>& texts) {
  for (const FigureText& t : texts) {
    cairo_set_source_rgb(cr, t.ink, t.ink, t.ink);
    show_text(cr, t.text, t.size_px, t.x, t.y, t.anchor_x, t.anchor_y, false, t.bold, t.wrap_px);
  }
}

}  // namespace

void draw_annotations(std::vector<float>& rgba, int width, int height, const Annotations& a,
                      const ColorManagement& color) {
  for (const PlacedLegend& l : a.legends) draw_legend(rgba, width, height, l.layout, l.scale, color, l.ink);
  if (a.texts.empty()) return;
  CairoOwned<cairo_surface_t> layer(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  {
    const CairoOwned<cairo_t> cr(cairo_create(layer.get()));
    draw_texts(cr.get(), a.texts);
  }
  composite_layer(layer.get(), 0, 0, rgba, width, height);
}

void draw_annotations(cairo_t* cr, const Annotations& a, const ColorManagement& color) {
  for (const PlacedLegend& l : a.legends) draw_legend(cr, l.layout, l.scale, color, l.ink);
  draw_texts(cr, a.texts);
}

}  // namespace hsb
