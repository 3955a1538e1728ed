#pragma once
// Text for figures, laid out by Pango with a real font (DejaVu Sans) and
// drawn by Cairo: Unicode titles, labels and captions ("λ₃ (MPa)", "(a)"),
// the same on a raster picture and on a PDF or SVG page.

#include <cairo.h>

#include <memory>
#include <string>
#include <vector>

namespace hsb {

struct CairoDeleter {
  void operator()(cairo_t* cr) const { cairo_destroy(cr); }
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
  void operator()(cairo_pattern_t* pattern) const { cairo_pattern_destroy(pattern); }
};
template <class T>
using CairoOwned = std::unique_ptr<T, CairoDeleter>;

// A context to measure text with: text sizes do not depend on the surface.
CairoOwned<cairo_t> measuring_context();

// `text`'s logical size at `size_px`, in the context's units, its lines
// wrapped at `wrap_px` when that is > 0 (as show_text wraps them).
void text_size(cairo_t* cr, const std::string& text, double size_px, double& width, double& height,
               bool bold = false, double wrap_px = 0.0);

// `text` with its anchor at (x, y): ax, ay in [0, 1] from its left/top to
// its right/bottom; rotated a quarter turn anticlockwise when `upright`.
// Lines wrap at `wrap_px` when it is > 0 (centred).
void show_text(cairo_t* cr, const std::string& text, double size_px, double x, double y, double ax, double ay,
               bool upright = false, bool bold = false, double wrap_px = 0.0);

// Composites what was drawn on `layer` (Cairo ARGB32, premultiplied) over
// display-referred, premultiplied RGBA `rgba` (width × height), `layer`'s
// top-left corner at (left, top).
void composite_layer(cairo_surface_t* layer, int left, int top, std::vector<float>& rgba, int width, int height);

}  // namespace hsb
