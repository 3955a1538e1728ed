#include "renderer/image/image_output.h"

#include "base/file_extension.h"
#include "base/input_file.h"
#include "base/partial_file.h"
#include "renderer/image/image_io_module.h"
#include "renderer/image/raster_stream.h"

#include <stdexcept>
#include <vector>

namespace hsb {

bool is_supported_image_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".png" || ext == ".tif" || ext == ".tiff" || ext == ".exr" || is_vector_format(path);
}

bool is_scene_linear_format(const std::string& path) { return lower_extension(path) == ".exr"; }

bool is_vector_format(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".pdf" || ext == ".svg";
}

namespace {

// How much of a figure is read for its hash, at either end: cairo writes a
// PDF's document information (the hash in its Keywords) last, before the
// cross-reference table; hsb puts an SVG's metadata first, after the
// <svg> tag, where a scene's texts come to 64 kB each, escaped at most
// sixfold (picture_output.cpp). The pictures in between, however large,
// are not read.
constexpr std::size_t kFigureEndBytes = 1 << 20;

std::string stored_figure_sha1(const std::string& path) {
  const bool pdf = lower_extension(path) == ".pdf";
  // Complete only with its ending: a PDF's last %%EOF, an SVG's </svg>.
  const std::string tail = file_tail(path, kFigureEndBytes);
  const std::string ending = pdf ? "%%EOF" : "</svg>";
  const std::size_t end = tail.rfind(ending);
  if (end == std::string::npos || tail.find_first_not_of(" \r\n", end + ending.size()) != std::string::npos) return "";
  // "hsb:scene_sha1=HEX" in a PDF's Keywords, the last of the document
  // information's texts (a scene's text before it in the Subject may spell
  // the same); key="hsb:scene_sha1">HEX in an SVG's <metadata>.
  const std::string text = pdf ? tail : file_head(path, kFigureEndBytes);
  const std::string marker = pdf ? "hsb:scene_sha1=" : "key=\"hsb:scene_sha1\">";
  const std::size_t at = pdf ? text.rfind(marker) : text.find(marker);
  if (at == std::string::npos || at + marker.size() + 40 > text.size()) return "";
  return text.substr(at + marker.size(), 40);
}

// Whether `head` begins as a file of the raster format `extension` does:
// only then is the file handed to OpenImageIO, whose readers would each be
// tried on it in turn, and one of which may take it for an image of its
// own format (a PNM header under a .png name declared 65535² pixels, and
// a run spent 17 GB and 40 s decoding them).
bool has_signature(const std::string& head, const std::string& extension) {
  const auto starts = [&](const char* bytes, std::size_t n) { return head.compare(0, n, bytes, n) == 0; };
  if (extension == ".png") return starts("\x89PNG\r\n\x1a\n", 8);
  if (extension == ".exr") return starts("\x76\x2f\x31\x01", 4);
  // TIFF, either byte order, classic or BigTIFF.
  return starts("II*\0", 4) || starts("MM\0*", 4) || starts("II+\0", 4) || starts("MM\0+", 4);
}

}  // namespace

std::string stored_scene_sha1(const std::string& path) {
  if (!unreadable_input(path).empty()) return "";
  if (is_vector_format(path)) return stored_figure_sha1(path);
  if (!has_signature(file_head(path, 8), lower_extension(path))) return "";
  return image_io().stored_sha1(path);
}

void write_image(const ImageToWrite& image, const std::string& path) {
  const std::string ext = lower_extension(path);
  if (!is_supported_image_path(path) || is_vector_format(path))
    throw std::runtime_error(path + ": unsupported image format \"" + ext + "\" (expected .png, .tif, .tiff or .exr)");
  if (ext != ".exr") {
    // PNG and TIFF: the whole picture as one band of a stream, the one
    // way their integer samples are made.
    const RasterStream::Format format{image.width, image.height, image.channels, image.bit_depth, image.dpi};
    RasterStream stream(path, format, [&] { return image.metadata; });
    stream.write_rows({image.pixels.data(), image.width, image.height, 0, image.channels, image.channels});
    stream.finish();
    return;
  }
  if (image.bit_depth != 16 && image.bit_depth != 32)
    throw std::runtime_error(path + ": an EXR's bit depth must be 16 (half) or 32 (float)");
  PartialFile file(path);
  std::vector<unsigned char> memory;
  try {
    image_io().encode(image, ext, file.path(), memory);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  if (!memory.empty()) file.write(memory.data(), memory.size());
  file.commit();
}

}  // namespace hsb
