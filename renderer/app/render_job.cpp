#include "renderer/app/render_job.h"

#include <OpenImageIO/hash.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>

#include "renderer/app/prepared_scene.h"
#include "renderer/image/color_management.h"
#include "renderer/image/colorbar.h"
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

// The scene's text and overrides: what its hash covers.
std::string scene_fingerprint(const SceneSpec& spec) {
  std::string text = spec.text;
  for (const std::string& o : spec.overrides) text += "\n--set " + o;
  return text;
}

std::map<std::string, std::string> image_metadata(const SceneSpec& spec, const ColorScale& scale,
                                                  const ColorManagement& color, std::size_t sources) {
  std::ostringstream description;
  description << "Hyperstreamball render of " << std::filesystem::path(spec.path).filename().string()
              << ": " << sources << " sources, kernel " << kernel_name(spec.surface.kernel)
              << ", R " << spec.surface.influence_radius << ", C " << spec.surface.isovalue
              << ", colour " << scale.map->name << " [" << scale.lo << ", " << scale.hi << "]";
  return {
      {"Software", std::string("Hyperstreamball ") + HSB_VERSION},
      {"ImageDescription", description.str()},
      {"hsb:scene", spec.path},
      {"hsb:scene_sha1", sha1_hex(scene_fingerprint(spec))},
      {"hsb:sources", std::to_string(sources)},
      {"hsb:kernel", kernel_name(spec.surface.kernel)},
      {"hsb:color_range", std::to_string(scale.lo) + " " + std::to_string(scale.hi)},
      {"hsb:ocio", color.config_name() + " / " + color.display() + " / " + color.view()},
  };
}

}  // namespace

RenderSummary run_render_job(const RenderJob& job) {
  const auto start = Clock::now();
  SceneSpec loaded = load_scene_or_data_file(job.scene_path, job.overrides);
  const ColorManagement color(loaded.output.display.value_or(""), loaded.output.view.value_or(""));
  const std::unique_ptr<PreparedScene> prepared = prepare_scene(std::move(loaded), color);
  const SceneSpec& spec = prepared->spec;
  const BlobField& field = prepared->field;
  const ColorScale& scale = prepared->scale;

  static const EmbreeDevice device;
  const RayScene scene(device, field, prepared->trace, prepared->context);
  const double build_seconds = seconds_since(start);
  RenderOutput rendered = render_image(scene, prepared->camera, prepared->shading, prepared->render);

  // Image: display transform (or scene-linear EXR), colour bar, metadata.
  const auto output_start = Clock::now();
  const std::filesystem::path image_path = std::filesystem::path(job.output_dir) / prepared->output.file;
  std::filesystem::create_directories(image_path.parent_path());
  Film& film = rendered.film;
  ImageToWrite image;
  image.width = film.width();
  image.height = film.height();
  image.bit_depth = prepared->output.bit_depth;
  image.metadata = image_metadata(spec, scale, color, field.sources.size());
  const std::size_t pixels = std::size_t(film.width()) * std::size_t(film.height());
  const std::vector<float>& rgb = film.data(Plane::color);
  const std::vector<float>& alpha = film.data(Plane::alpha);
  if (is_scene_linear_format(image_path.string())) {
    // EXR keeps scene-linear data, with the camera distance as a Z channel.
    image.channels = 5;
    image.channel_names = {"R", "G", "B", "A", "Z"};
    image.pixels.resize(pixels * 5);
    const std::vector<float>& depth = film.data(Plane::depth);
    for (std::size_t i = 0; i < pixels; ++i) {
      for (int c = 0; c < 3; ++c) image.pixels[i * 5 + std::size_t(c)] = rgb[i * 3 + std::size_t(c)];
      image.pixels[i * 5 + 3] = alpha[i];
      image.pixels[i * 5 + 4] = depth[i];
    }
  } else {
    // The display transform works on colours, not on colours times
    // coverage: undo the premultiplication around it.
    const bool transparent = prepared->shading.background_kind == BackgroundKind::transparent;
    std::vector<float> rgba(pixels * 4);
    for (std::size_t i = 0; i < pixels; ++i) {
      const float a = transparent ? alpha[i] : 1.0f;
      for (int c = 0; c < 3; ++c) rgba[i * 4 + std::size_t(c)] = a > 0.0f ? rgb[i * 3 + std::size_t(c)] / a : 0.0f;
      rgba[i * 4 + 3] = a;
    }
    film = Film(1, 1);  // its memory is no longer needed
    color.apply_display(rgba, image.width, image.height);
    for (std::size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 3; ++c) rgba[i * 4 + std::size_t(c)] *= rgba[i * 4 + 3];
    if (prepared->output.colorbar)
      draw_colorbar(rgba, image.width, image.height, scale, {prepared->output.colorbar_title}, color);
    image.pixels = std::move(rgba);
  }
  write_image(image, image_path.string());

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
