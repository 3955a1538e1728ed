#include "renderer/image/vector_figure.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "base/file_extension.h"
#include "base/partial_file.h"

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

// `text` as XML 1.0 character data: its five special characters escaped,
// and what XML cannot hold at all (control characters but tab, line feed
// and carriage return; bytes that are not UTF-8; U+FFFE, U+FFFF) as U+FFFD,
// so that a name or a value from a user's file never makes the figure
// malformed.
std::string xml_escaped(const std::string& text) {
  static const std::string replacement = "\xEF\xBF\xBD";
  std::string out;
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n;) {
    const unsigned char c = bytes[i];
    if (c < 0x80) {
      switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        default: out += (c < 0x20 && c != '\t' && c != '\n' && c != '\r') ? replacement : std::string(1, char(c));
      }
      ++i;
      continue;
    }
    // A UTF-8 sequence: its length from the lead byte, each continuation
    // byte 10xxxxxx, no overlong form, no surrogate, nothing past U+10FFFF.
    const std::size_t length = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c <= 0xDF ? 2 : 0;
    std::uint32_t code = length == 4 ? c & 0x07u : length == 3 ? c & 0x0Fu : c & 0x1Fu;
    bool valid = length != 0 && i + length <= n && c < 0xF5;
    for (std::size_t k = 1; valid && k < length; ++k) {
      valid = (bytes[i + k] & 0xC0) == 0x80;
      code = (code << 6) | (bytes[i + k] & 0x3Fu);
    }
    valid = valid && !(length == 3 && code < 0x800) && !(length == 4 && (code < 0x10000 || code > 0x10FFFF)) &&
            !(code >= 0xD800 && code <= 0xDFFF) && code != 0xFFFE && code != 0xFFFF;
    out += valid ? text.substr(i, length) : replacement;
    i += valid ? length : 1;
  }
  return out;
}

// Cairo writes no metadata into an SVG: add a <metadata> element, one
// entry a key, right after the opening <svg> tag.
void add_svg_metadata(const std::string& path, const std::map<std::string, std::string>& metadata) {
  std::string svg;
  {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    svg = text.str();
  }
  const std::size_t open = svg.find("<svg");
  const std::size_t end = open == std::string::npos ? open : svg.find('>', open);
  if (end == std::string::npos) throw std::runtime_error(path + ": cairo wrote no <svg> element");
  std::string block = "\n<metadata>\n";
  for (const auto& [key, value] : metadata)
    block += "<hsb:entry xmlns:hsb=\"urn:hyperstreamball\" key=\"" + xml_escaped(key) + "\">" + xml_escaped(value) +
             "</hsb:entry>\n";
  block += "</metadata>";
  svg.insert(end + 1, block);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << svg;
  if (!out.flush()) throw std::runtime_error(path + ": cannot write the figure's metadata");
}

// The value of `key`, or "".
std::string entry(const std::map<std::string, std::string>& metadata, const char* key) {
  const auto it = metadata.find(key);
  return it == metadata.end() ? "" : it->second;
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
    // Cairo 1.16 writes only the standard document information: the
    // hashes go into Keywords, the scene and its resolved values into
    // Subject, after the description.
    const auto& m = f.metadata;
    const std::string keywords = "hsb:scene_sha1=" + entry(m, "hsb:scene_sha1") +
                                 "; hsb:data_sha1=" + entry(m, "hsb:data_sha1") +
                                 "; hsb:data_file=" + entry(m, "hsb:data_file");
    const std::string subject = entry(m, "ImageDescription") + "\n\nScene:\n" + entry(m, "hsb:scene_text") +
                                "\n\nResolved:\n" + entry(m, "hsb:resolved");
    cairo_pdf_surface_set_metadata(page, CAIRO_PDF_METADATA_CREATOR, entry(m, "Software").c_str());
    cairo_pdf_surface_set_metadata(page, CAIRO_PDF_METADATA_TITLE, entry(m, "hsb:scene").c_str());
    cairo_pdf_surface_set_metadata(page, CAIRO_PDF_METADATA_SUBJECT, subject.c_str());
    cairo_pdf_surface_set_metadata(page, CAIRO_PDF_METADATA_KEYWORDS, keywords.c_str());
  }
  cairo_t* cr = cairo_create(page);
  // User space in the picture's pixels.
  cairo_scale(cr, points_per_pixel, points_per_pixel);
  cairo_surface_t* picture = picture_surface(f);
  cairo_set_source_surface(cr, picture, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);  // the pixels as rendered
  cairo_paint(cr);
  cairo_surface_destroy(picture);
  if (f.annotations) draw_annotations(cr, *f.annotations, color);
  cairo_destroy(cr);
  cairo_surface_finish(page);
  const cairo_status_t status = cairo_surface_status(page);
  cairo_surface_destroy(page);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(path + ": cannot write the figure: " + cairo_status_to_string(status));
  if (!pdf) add_svg_metadata(file.path(), f.metadata);
  file.commit();
}

}  // namespace hsb
