#include "renderer/app/render_job.h"

#include <OpenImageIO/hash.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "renderer/app/batch.h"
#include "renderer/app/pinned_scene.h"
#include "renderer/app/prepared_scene.h"
#include "renderer/image/color_management.h"
#include "renderer/image/display_image.h"
#include "renderer/image/legend.h"
#include "renderer/image/vector_figure.h"
#include "renderer/image/colormap.h"
#include "renderer/image/image_output.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/render_image.h"
#include "renderer/scene/scene_spec.h"

#ifndef HSB_VERSION
#define HSB_VERSION "unknown"
#endif

namespace hsb {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string sha1_hex(const std::string& text) {
  OIIO::SHA1 hash(text.data(), text.size());
  return hash.digest();
}

// The SHA-1 of a file's bytes; "" when there is no file.
std::string file_sha1(const std::string& path) {
  if (path.empty()) return "";
  std::ifstream in(path, std::ios::binary);
  OIIO::SHA1 hash;
  std::vector<char> buffer(1 << 20);
  while (in) {
    in.read(buffer.data(), std::streamsize(buffer.size()));
    hash.append(buffer.data(), std::size_t(in.gcount()));
  }
  return hash.digest();
}

// The scene's text and overrides.
std::string scene_text(const SceneSpec& spec) {
  std::string text = spec.text;
  for (const std::string& o : spec.overrides) text += "\n--set " + o;
  return text;
}

const std::string& data_file_of(const SceneSpec& spec) {
  static const std::string none;
  return spec.pipeline.data.kind == DataKind::vtk_file ? spec.pipeline.data.file.path : none;
}

// Everything the picture is made from as written in the image: the scene,
// its overrides and, by its hash, the data file.
std::map<std::string, std::string> image_metadata(const PreparedScene& prepared, const ColorManagement& color) {
  const SceneSpec& spec = prepared.spec;
  const ColorScale& scale = prepared.scale;
  const std::size_t sources = prepared.field.sources.size();
  const std::string& data_file = data_file_of(spec);
  const std::string data_sha1 = file_sha1(data_file);
  const std::string text = scene_text(spec);
  std::ostringstream description;
  description << "Hyperstreamball render of " << std::filesystem::path(spec.path).filename().string()
              << ": " << sources << " sources, kernel " << kernel_name(spec.surface.kernel)
              << ", R " << spec.surface.influence_radius << ", C " << spec.surface.isovalue
              << ", colour " << scale.map->name << " [" << scale.lo << ", " << scale.hi << "]";
  return {
      {"Software", std::string("Hyperstreamball ") + HSB_VERSION},
      {"ImageDescription", description.str()},
      {"hsb:scene", spec.path},
      {"hsb:scene_text", text},
      {"hsb:scene_sha1", scene_sha1(spec)},
      {"hsb:data_file", data_file},
      {"hsb:data_sha1", data_sha1},
      {"hsb:resolved", pinned_scene_toml(prepared)},
      {"hsb:sources", std::to_string(sources)},
      {"hsb:kernel", kernel_name(spec.surface.kernel)},
      {"hsb:color_range", std::to_string(scale.lo) + " " + std::to_string(scale.hi)},
      {"hsb:ocio", color.config_name() + " / " + color.display() + " / " + color.view()},
  };
}

}  // namespace

namespace {

// The EXR's channels: RGBA, then each of the film's other planes.
ImageToWrite scene_linear_image(const Film& film) {
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
  return image;
}

}  // namespace

std::string scene_sha1(const SceneSpec& spec) {
  return sha1_hex(scene_text(spec) + "\n" + file_sha1(data_file_of(spec)));
}

RenderSummary run_render_job(const RenderJob& job) {
  const auto start = Clock::now();
  const auto report = [&](JobStage stage, double fraction) {
    if (job.progress) job.progress(stage, fraction);
  };
  report(JobStage::preparing, 0.0);
  SceneSpec loaded = load_scene_or_data_file(job.scene_path, job.overrides);
  if (job.skip_existing) {
    const std::string existing =
        (std::filesystem::path(job.output_dir) / file_for_variant(output_file_name(loaded), job.variant)).string();
    if (stored_scene_sha1(existing) == scene_sha1(loaded)) {
      RenderSummary skipped;
      skipped.image_path = existing;
      skipped.skipped = true;
      return skipped;
    }
  }
  const ColorManagement color = scene_color_management(loaded);
  const std::unique_ptr<PreparedScene> prepared = prepare_scene(std::move(loaded), color);
  prepared->output.file = file_for_variant(prepared->output.file, job.variant);
  const SceneSpec& spec = prepared->spec;
  const BlobField& field = prepared->field;
  const ColorScale& scale = prepared->scale;
  const OutputSettings& output = prepared->output;

  static const EmbreeDevice device;
  const RayScene scene(device, field, prepared->trace, prepared->context);
  const double build_seconds = seconds_since(start);
  RenderSettings settings = prepared->render;
  settings.progress = [&](double fraction) { report(JobStage::rendering, fraction); };
  report(JobStage::rendering, 0.0);
  RenderOutput rendered = render_image(scene, prepared->camera, prepared->shading, settings);

  // Render → result (the film) → display image → annotation → file.
  report(JobStage::writing, 1.0);
  const auto output_start = Clock::now();
  const std::filesystem::path image_path = std::filesystem::path(job.output_dir) / output.file;
  std::filesystem::create_directories(image_path.parent_path());
  std::map<std::string, std::string> metadata = image_metadata(*prepared, color);
  if (is_scene_linear_format(image_path.string())) {
    ImageToWrite image = scene_linear_image(rendered.film);
    image.bit_depth = output.bit_depth;
    image.dpi = output.dpi;
    image.metadata = std::move(metadata);
    write_image(image, image_path.string());
  } else {
    const int width = rendered.film.width(), height = rendered.film.height();
    const bool transparent = prepared->shading.background_kind == BackgroundKind::transparent;
    std::vector<float> rgba = display_pixels(rendered.film, color, transparent);
    rendered.film = Film(1, 1);  // its memory is no longer needed
    const LegendLayout* legend = output.legend ? &*output.legend : nullptr;
    const float ink = legend ? ink_over(rgba, width, std::clamp(int(legend->bar_x0) - 2, 0, width - 1),
                                        std::clamp(int(legend->bar_y0), 0, height - 1))
                             : 0.0f;
    if (is_vector_format(image_path.string())) {
      VectorFigure figure{&rgba, width, height, output.dpi, legend, &scale, ink, std::move(metadata)};
      write_vector_figure(figure, color, image_path.string());
    } else {
      if (legend) draw_legend(rgba, width, height, *legend, scale, color, ink);
      ImageToWrite image;
      image.width = width;
      image.height = height;
      image.bit_depth = output.bit_depth;
      image.dpi = output.dpi;
      image.metadata = std::move(metadata);
      image.pixels = std::move(rgba);
      write_image(image, image_path.string());
    }
  }

  RenderSummary summary;
  summary.image_path = image_path.string();
  summary.warnings = prepared->warnings;
  summary.trajectories = prepared->glyphs.trajectories.size();
  summary.sources = field.sources.size();
  summary.build_seconds = build_seconds;
  summary.render_seconds = rendered.seconds;
  summary.output_seconds = seconds_since(output_start);
  summary.total_seconds = seconds_since(start);
  summary.primary_rays = rendered.primary_rays;
  summary.shadow_rays = rendered.shadow_rays;
  summary.primary_mrays_per_second = rendered.primary_mrays_per_second();
  summary.shadow_mrays_per_second = rendered.shadow_mrays_per_second();
  summary.stats = rendered.stats;
  return summary;
}

}  // namespace hsb
