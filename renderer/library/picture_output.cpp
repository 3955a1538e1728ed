#include "renderer/library/picture_output.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "base/input_file.h"
#include "base/sha1.h"
#include "field/reading/data_error.h"
#include "field/reading/vtk_data.h"
#include "renderer/image/color_management.h"
#include "renderer/image/display_image.h"
#include "renderer/image/image_output.h"
#include "renderer/image/vector_figure.h"

#ifndef HSB_VERSION
#define HSB_VERSION "unknown"
#endif

namespace hsb {
namespace {

// The SHA-1 of `file`'s bytes, as many as it had when opened: a file that
// grows meanwhile is hashed as it was, never without end.
std::string sha1_of(const InputFile& file) {
  Sha1 hash;
  std::vector<char> buffer(1 << 20);
  for (std::uint64_t at = 0; at < file.size();) {
    const std::size_t n = file.read(at, buffer.data(), buffer.size());
    if (n == 0) break;  // cut short meanwhile
    hash.append(buffer.data(), n);
    at += n;
  }
  return hash.hex();
}

// Why `file`, named as `named`, is not hashed: hashing a FIFO would wait
// for a writer for ever, a device (/dev/zero) would never end. "" for a
// file hsb reads, and for one that is not there, which hashes as empty
// (its reading says where it is missing).
std::string unhashed(const InputFile& file, const std::string& named) {
  return file.why().empty() || file.why() == "no such file" ? "" : named + ": " + file.why();
}

// The SHA-1 of the file at `path`; "" when there is no file.
std::string file_sha1(const std::string& path) {
  if (path.empty()) return "";
  const InputFile file(path);
  if (const std::string why = unhashed(file, path); !why.empty()) throw std::runtime_error(why);
  return sha1_of(file);
}

// The SHA-1 of `path`, the data file `data` or a file it names, said as
// reading the data would say it.
std::string data_file_sha1(const std::string& data, const std::string& path) {
  const InputFile file(path);
  if (const std::string why = unhashed(file, path == data ? data : data + ": names " + path); !why.empty())
    throw DataError(why);
  return sha1_of(file);
}

// The scene's text and overrides.
std::string scene_text(const SceneSpec& spec) {
  std::string text = spec.text;
  for (const std::string& o : spec.overrides) text += "\n--set " + o;
  return text;
}

// The file the picture's data comes from: a data file, or a source list.
std::string data_file_of(const SceneSpec& spec) {
  if (spec.pipeline.data.kind == DataKind::vtk_file) return spec.pipeline.data.file.path;
  if (spec.pipeline.placement == SourcePlacement::list) return spec.pipeline.list_file;
  return "";
}

// The SHA-1 of the data: of its file, or for data read from several (a
// series' step, pieces, blocks) of their SHA-1s in turn.
std::string data_sha1(const SceneSpec& spec) {
  if (spec.pipeline.data.file.arrays) return arrays_sha1(*spec.pipeline.data.file.arrays);
  const std::string data = data_file_of(spec);
  if (spec.pipeline.data.kind != DataKind::vtk_file) return file_sha1(data);
  const std::vector<std::string> files = data_files_read(data, spec.pipeline.data.file.step);
  if (files.size() == 1) return data_file_sha1(data, files.front());
  std::string hashes;
  for (const std::string& file : files) hashes += data_file_sha1(data, file) + "\n";
  return sha1_hex(hashes);
}

// The colour configuration the picture goes through: output.ocio_config,
// else $OCIO, else the built-in one (the same in every build); with the
// LUTs it reads, whose change changes the picture as the file's does.
std::string color_config_sha1(const SceneSpec& spec) {
  const char* environment = std::getenv("OCIO");
  const bool from_scene = !spec.output.ocio_config.empty();
  const std::string file = from_scene ? spec.output.ocio_config : (environment && *environment ? environment : "");
  if (file.empty()) return "built-in";
  const InputFile config(file);
  if (!config.why().empty())
    throw std::runtime_error(std::string(from_scene ? "output.ocio_config" : "$OCIO") + " names " + file + ": " +
                             config.why());
  const std::vector<std::string> luts = color_config_luts(file);
  if (luts.empty()) return sha1_of(config);
  std::string hashes = sha1_of(config) + "\n";
  for (const std::string& lut : luts) {
    const InputFile read(lut);
    if (!read.why().empty()) throw std::runtime_error(lut + ": " + read.why());
    hashes += sha1_of(read) + "\n";
  }
  return sha1_hex(hashes);
}

// The scene hash from the data file's, so the file is read once. With the
// colour configuration's: the same scene through another config is
// another picture.
std::string scene_sha1(const SceneSpec& spec, const std::string& data_sha1) {
  return sha1_hex(scene_text(spec) + "\n" + data_sha1 + "\nocio " + color_config_sha1(spec));
}

}  // namespace

std::string scene_sha1(const SceneSpec& spec) { return scene_sha1(spec, data_sha1(spec)); }

std::string picture_description(const PreparedScene& prepared) {
  const SceneSpec& spec = prepared.spec;
  const ColorScale& scale = prepared.scale;
  std::ostringstream description;
  description << prepared.field.sources.size() << " sources, kernel " << kernel_name(spec.surface.kernel) << ", R "
              << spec.surface.influence_radius << ", C " << spec.surface.isovalue << ", colour " << scale.map->name
              << " [" << scale.lo << ", " << scale.hi << "]";
  return description.str();
}

namespace {

// Text kept whole in every image up to this size. A larger scene (a point
// list of thousands of seeds, a 50 MB comment) would be copied into each
// image of a batch; its size and SHA-1 name it instead, which is what
// comparing two images' scenes needs.
constexpr std::size_t kMetadataTextBytes = 64 * 1024;

std::string metadata_text(const std::string& text) {
  if (text.size() <= kMetadataTextBytes) return text;
  return "(" + std::to_string(text.size()) + " bytes, more than an image keeps; SHA-1 " + sha1_hex(text) + ")";
}

}  // namespace

std::map<std::string, std::string> picture_metadata(const SceneSpec& spec, const std::string& description,
                                                    const std::string& resolved, const ColorManagement& color) {
  const std::string data_file = data_file_of(spec);
  const std::string data_hash = data_sha1(spec);
  return {
      {"Software", std::string("Hyperstreamball ") + HSB_VERSION},
      {"ImageDescription",
       "Hyperstreamball render of " + std::filesystem::path(spec.path).filename().string() + ": " + description},
      {"hsb:scene", spec.path},
      {"hsb:scene_text", metadata_text(scene_text(spec))},
      {"hsb:scene_sha1", scene_sha1(spec, data_hash)},
      {"hsb:data_file", data_file},
      {"hsb:data_sha1", data_hash},
      {"hsb:resolved", metadata_text(resolved)},
      {"hsb:kernel", kernel_name(spec.surface.kernel)},
      {"hsb:ocio", color.config_name() + " / " + color.display() + " / " + color.view()},
  };
}

RasterStream::Format display_raster_format(int width, int height, const OutputSettings& output, bool transparent) {
  return {width, height, transparent ? 4 : 3, output.bit_depth, output.dpi};
}

float legend_ink(const std::vector<float>& rgba, int width, int height, const LegendLayout& legend) {
  const std::array<double, 2> at = legend.ink_sample();
  return ink_over(rgba, width, std::clamp(int(at[0]), 0, width - 1), std::clamp(int(at[1]), 0, height - 1));
}

void write_display_picture(const std::string& path, std::vector<float> rgba, int width, int height, bool transparent,
                           const Annotations& annotations, const OutputSettings& output,
                           std::map<std::string, std::string> metadata, const ColorManagement& color) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  if (is_vector_format(path)) {
    const VectorFigure figure{&rgba, width, height, output.dpi, &annotations, std::move(metadata)};
    write_vector_figure(figure, color, path);
    return;
  }
  draw_annotations(rgba, width, height, annotations, color);
  const RasterStream::Format format = display_raster_format(width, height, output, transparent);
  RasterStream stream(path, format, [&] { return std::move(metadata); });
  stream.write_rows({rgba.data(), width, height, 0, 4, format.channels});
  stream.finish();
}

void write_scene_linear_picture(const std::string& path, const Film& film, const OutputSettings& output,
                                std::map<std::string, std::string> metadata) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  ImageToWrite image;
  image.width = film.width();
  image.height = film.height();
  const std::vector<Plane> planes = film.planes();
  image.channels = 0;
  for (Plane p : planes) {
    const PlaneInfo& info = plane_info(p);
    for (int c = 0; c < info.channels; ++c) {
      if (p == Plane::id) image.integer_channels.push_back(image.channels);
      image.channel_names.push_back(info.channel_names[std::size_t(c)]);
      ++image.channels;
    }
  }
  const std::size_t pixels = std::size_t(film.width()) * std::size_t(film.height());
  image.pixels.resize(pixels * std::size_t(image.channels));
  std::size_t offset = 0;
  for (Plane p : planes) {
    const std::vector<float>& data = film.data(p);
    const std::size_t n = std::size_t(plane_info(p).channels);
    for (std::size_t i = 0; i < pixels; ++i)
      for (std::size_t c = 0; c < n; ++c) {
        float v = data[i * n + c];
        if (p == Plane::id) v += 1.0f;  // unsigned: 0 where no glyph, else the source's index + 1
        image.pixels[i * std::size_t(image.channels) + offset + c] = v;
      }
    offset += n;
  }
  image.bit_depth = output.bit_depth;
  image.dpi = output.dpi;
  image.metadata = std::move(metadata);
  write_image(image, path);
}

}  // namespace hsb
