#pragma once
// Writing finished raster images through OpenImageIO.

#include <map>
#include <string>
#include <vector>

namespace hsb {

struct ImageToWrite {
  int width = 0, height = 0;
  int channels = 4;
  std::vector<std::string> channel_names;  // empty: OIIO's defaults (R, G, B, A)
  std::vector<float> pixels;               // width*height*channels, top row first; colour premultiplied by alpha
  // PNG and TIFF: 8 or 16 bits an integer channel. EXR: 16 (half) or 32
  // (float) bits.
  int bit_depth = 8;
  std::vector<int> integer_channels;  // EXR: channels stored as 32-bit unsigned integers (ids)
  double dpi = 0.0;                   // written as the image's resolution when > 0
  std::map<std::string, std::string> metadata;
};

// Writes `image` to `path`, the format chosen by the extension (.png, .tif,
// .tiff, .exr). The file appears complete or not at all: it is written under
// a temporary name in the same folder and renamed into place. Throws
// std::runtime_error with OIIO's message on failure.
void write_image(const ImageToWrite& image, const std::string& path);

// True for every extension a picture can be written to: .png, .tif,
// .tiff, .exr (write_image), .pdf, .svg (vector_figure.h); any case.
bool is_supported_image_path(const std::string& path);
// True for extensions whose images hold scene-linear data (EXR).
bool is_scene_linear_format(const std::string& path);
// True for the vector formats, PDF and SVG.
bool is_vector_format(const std::string& path);

// The scene hash (hsb:scene_sha1) stored in an image this program wrote:
// from the metadata of a PNG or EXR (a TIFF keeps none), from a PDF's
// keywords or an SVG's <metadata>. "" when the file is missing, unreadable
// or holds none. Reads only what that needs, whatever the file: a figure's
// two ends, and a raster image only when its first bytes are those of the
// format its name says, decoded a band of rows at a time.
std::string stored_scene_sha1(const std::string& path);

}  // namespace hsb
