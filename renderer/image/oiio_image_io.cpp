// The image module (image_io_module.h): hsb's every use of OpenImageIO,
// built as libhsb_image_io.so and loaded when first needed.

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/image/dither.h"
#include "renderer/image/image_io_module.h"

namespace hsb {
namespace {

void encode(const ImageToWrite& image, const std::string& extension, const std::string& file,
            std::vector<char>& memory) {
  const bool exr = extension == ".exr";
  const OIIO::TypeDesc format = exr ? (image.bit_depth == 16 ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT)
                                    : (image.bit_depth == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
  OIIO::ImageSpec spec(image.width, image.height, image.channels, format);
  if (!image.channel_names.empty()) spec.channelnames = image.channel_names;
  if (image.channels >= 4) spec.alpha_channel = 3;
  if (exr && !image.integer_channels.empty()) {
    spec.channelformats.assign(std::size_t(image.channels), format);
    for (int c : image.integer_channels) spec.channelformats[std::size_t(c)] = OIIO::TypeDesc::UINT;
  }
  if (exr) spec.attribute("compression", "zip");
  // PNG encoding is the one single-threaded step after the render. One row
  // filter (Sub) instead of libpng's per-row trial of all five, and zlib
  // level 3 instead of 6, halve it (0.24 s -> 0.12 s for the 800×800
  // cylinder figure) for files about 12% larger.
  if (extension == ".png") {
    spec.attribute("png:filter", 16);  // PNG_FILTER_SUB
    spec.attribute("png:compressionLevel", 3);
  }
  if (image.dpi > 0.0) {
    spec.attribute("XResolution", float(image.dpi));
    spec.attribute("YResolution", float(image.dpi));
    spec.attribute("ResolutionUnit", "inch");
  }
  for (const auto& [key, value] : image.metadata) spec.attribute(key, value);

  // Where the format can, the encoder writes into memory, for the caller
  // to write with every write checked: libpng's own file output ignores a
  // full disk and leaves a truncated image.
  OIIO::Filesystem::IOVecOutput buffer;
  auto out = OIIO::ImageOutput::create(file);
  if (!out) throw std::runtime_error(OIIO::geterror());
  const bool in_memory = out->supports("ioproxy") && out->set_ioproxy(&buffer);
  // Dithered to 8 bits so smooth shading does not band (dither.h): on
  // every core, where OIIO's own oiio:dither adds its blue noise and
  // converts a row at a time on one, 0.1 s of a 4-megapixel PNG's time.
  const std::vector<unsigned char> bytes =
      format == OIIO::TypeDesc::UINT8
          ? dithered_8bit(image.pixels, image.width, image.height, image.channels, spec.alpha_channel)
          : std::vector<unsigned char>();
  const bool ok = out->open(file, spec) &&
                  (bytes.empty() ? out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data())
                                 : out->write_image(OIIO::TypeDesc::UINT8, bytes.data())) &&
                  out->close();
  if (!ok) throw std::runtime_error(out->geterror());
  out.reset();
  if (in_memory) memory.assign(buffer.buffer().begin(), buffer.buffer().end());
}

std::string stored_sha1(const std::string& path) {
  // Decoded whole, not only its header: a file cut short (a disk that
  // filled, a copy interrupted) holds the right hash and a broken
  // picture, and must be rendered again.
  auto in = OIIO::ImageInput::open(path);
  if (!in) return "";
  const std::string hash = in->spec().get_string_attribute("hsb:scene_sha1");
  std::vector<float> pixels(in->spec().image_pixels() * std::size_t(in->spec().nchannels));
  if (!in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) return "";
  return hash;
}

const ImageIo functions{encode, stored_sha1};

}  // namespace
}  // namespace hsb

extern "C" const hsb::ImageIo* hsb_image_io_functions() { return &hsb::functions; }
