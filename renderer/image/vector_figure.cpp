#include "renderer/image/vector_figure.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "field/file_extension.h"
#include "field/partial_file.h"

namespace hsb {
namespace {

// The picture as a Cairo image: 8-bit, premultiplied, native-endian ARGB.
cairo_surface_t* picture_surface(const VectorFigure& f) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, f.width, f.height);
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const auto byte = [](float v) { return std::uint32_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const float* p = &(*f.rgba)[(std::size_t(y) * std::size_t(f.width) + std::size_t(x)) * 4];
      *reinterpret_cast<std::uint32_t*>(data + y * stride + 4 * x) =
          (byte(p[3]) << 24) | (byte(p[0]) << 16) | (byte(p[1]) << 8) | byte(p[2]);
    }
  cairo_surface_mark_dirty(surface);
  return surface;
}

}  // namespace

void write_vector_figure(const VectorFigure& f, const ColorManagement& color, const std::string& path) {
  PartialFile file(path);
  // Page size in points: the picture prints at its DPI.
  const double points_per_pixel = 72.0 / f.dpi;
  const double page_w = f.width * points_per_pixel, page_h = f.height * points_per_pixel;
  const bool pdf = lower_extension(path) == ".pdf";
  cairo_surface_t* page = pdf ? cairo_pdf_surface_create(file.path().c_str(), page_w, page_h)
                              : cairo_svg_surface_create(file.path().c_str(), page_w, page_h);
  if (pdf) {
    const auto meta = [&](cairo_pdf_metadata_t key, const char* name) {
      const auto it = f.metadata.find(name);
      if (it != f.metadata.end()) cairo_pdf_surface_set_metadata(page, key, it->second.c_str());
    };
    meta(CAIRO_PDF_METADATA_CREATOR, "Software");
    meta(CAIRO_PDF_METADATA_SUBJECT, "ImageDescription");
    meta(CAIRO_PDF_METADATA_KEYWORDS, "hsb:scene_sha1");
  }
  cairo_t* cr = cairo_create(page);
  // User space in the picture's pixels.
  cairo_scale(cr, points_per_pixel, points_per_pixel);
  cairo_surface_t* picture = picture_surface(f);
  cairo_set_source_surface(cr, picture, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);  // the pixels as rendered
  cairo_paint(cr);
  cairo_surface_destroy(picture);
  if (f.legend && f.scale) draw_legend(cr, *f.legend, *f.scale, color, f.ink);
  cairo_destroy(cr);
  cairo_surface_finish(page);
  const cairo_status_t status = cairo_surface_status(page);
  cairo_surface_destroy(page);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(path + ": cannot write the figure: " + cairo_status_to_string(status));
  file.commit();
}

}  // namespace hsb
