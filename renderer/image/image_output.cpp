#include "renderer/image/image_output.h"

#include "base/file_extension.h"
#include "base/partial_file.h"
#include "renderer/image/image_io_module.h"
#include "renderer/image/raster_stream.h"

#include <filesystem>
#include <fstream>
#include <sstream>
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

std::string stored_scene_sha1(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) return "";
  if (!is_vector_format(path)) return image_io().stored_sha1(path);
  // Both vector formats keep it in plain text: "hsb:scene_sha1=HEX" in a
  // PDF's uncompressed document information, key="hsb:scene_sha1">HEX in an SVG.
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  // Complete only with its ending: a PDF's last %%EOF, an SVG's </svg>.
  const std::string ending = lower_extension(path) == ".pdf" ? "%%EOF" : "</svg>";
  const std::size_t end = s.rfind(ending);
  if (end == std::string::npos || s.find_first_not_of(" \r\n", end + ending.size()) != std::string::npos) return "";
  for (const std::string marker : {"hsb:scene_sha1=", "key=\"hsb:scene_sha1\">"}) {
    const std::size_t at = s.find(marker);
    if (at != std::string::npos && at + marker.size() + 40 <= s.size()) return s.substr(at + marker.size(), 40);
  }
  return "";
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
