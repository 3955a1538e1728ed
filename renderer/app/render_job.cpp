#include "renderer/app/render_job.h"

#include <chrono>
#include <filesystem>
#include <optional>

#include "renderer/app/batch.h"
#include "renderer/app/panel_figure.h"
#include "renderer/app/picture_output.h"
#include "renderer/app/pinned_scene.h"
#include "renderer/app/prepared_scene.h"
#include "renderer/image/display_image.h"
#include "renderer/image/image_output.h"
#include "renderer/image/raster_stream.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/render_image.h"

namespace hsb {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

RenderSummary run_render_job(const RenderJob& job) {
  const auto start = Clock::now();
  const auto report = [&](JobStage stage, double fraction) {
    if (job.progress) job.progress(stage, fraction);
  };
  report(JobStage::preparing, 0.0);
  SceneSpec loaded = load_scene_or_data_file(job.scene_path, job.overrides);
  const std::string file = file_for_variant(output_file_name(loaded), job.variant);
  const std::string image_path = (std::filesystem::path(job.output_dir) / file).string();
  if (job.written) {
    const std::string key = std::filesystem::weakly_canonical(image_path).string();
    const auto [earlier, fresh] = job.written->emplace(key, job.scene_path);
    if (!fresh)
      throw SceneError(job.scene_path + ": its image " + image_path + " is the one " + earlier->second +
                       " wrote earlier in this batch; give one of them another output.file or render them into "
                       "separate folders");
  }
  if (job.skip_existing && stored_scene_sha1(image_path) == scene_sha1(loaded)) {
    RenderSummary skipped;
    skipped.image_path = image_path;
    skipped.skipped = true;
    return skipped;
  }
  if (!loaded.panels.empty()) return render_panel_figure(std::move(loaded), image_path, job.progress);

  const ColorManagement color = scene_color_management(loaded);
  const std::unique_ptr<PreparedScene> prepared = prepare_scene(std::move(loaded), color);
  prepared->output.file = file;
  const OutputSettings& output = prepared->output;

  static const EmbreeDevice device;
  const RayScene scene(device, prepared->field, prepared->trace, prepared->context);
  const double build_seconds = seconds_since(start);
  RenderSettings settings = prepared->render;
  settings.progress = [&](double fraction) { report(JobStage::rendering, fraction); };
  const bool transparent = prepared->shading.background_kind == BackgroundKind::transparent;
  const auto metadata = [&, description = picture_description(*prepared), resolved = pinned_scene_toml(*prepared)] {
    return picture_metadata(prepared->spec, description, resolved, color);
  };
  // Render → result (the film) → display image → annotation → file; a
  // picture with nothing drawn over it goes to its file as it is made.
  std::optional<RasterStream> stream;
  if (output.streams()) {
    std::filesystem::create_directories(std::filesystem::path(image_path).parent_path());
    const RasterStream::Format format =
        display_raster_format(settings.width, settings.height, output, transparent);
    stream.emplace(image_path, format, metadata);
    settings.rows_done = [&, channels = format.channels, rgba = std::vector<float>()](const Film& film, int first,
                                                                                     int last) mutable {
      display_rows(film, first, last, color, transparent, rgba);
      stream->write_rows({rgba.data(), film.width(), last - first, first, 4, channels});
    };
  }
  report(JobStage::rendering, 0.0);
  RenderOutput rendered = render_image(scene, prepared->camera, prepared->shading, settings);

  report(JobStage::writing, 1.0);
  const auto output_start = Clock::now();
  if (stream) {
    stream->finish();
  } else if (is_scene_linear_format(image_path)) {
    write_scene_linear_picture(image_path, rendered.film, output, metadata());
  } else {
    const int width = rendered.film.width(), height = rendered.film.height();
    std::vector<float> rgba = display_pixels(std::move(rendered.film), color, transparent);
    rendered.film = Film(1, 1);  // the rest of its memory is no longer needed
    Annotations annotations;
    if (output.legend)
      annotations.legends.push_back({*output.legend, prepared->scale, legend_ink(rgba, width, height, *output.legend)});
    write_display_picture(image_path, std::move(rgba), width, height, transparent, annotations, output, metadata(),
                          color);
  }

  RenderSummary summary;
  summary.image_path = image_path;
  summary.warnings = prepared->warnings;
  // A picture without the glyphs it was asked for is no success.
  if (prepared->context.glyphs && !prepared->field.sources.empty() && rendered.stats.glyph_hits == 0)
    summary.warnings.push_back("none of the " + std::to_string(prepared->field.sources.size()) +
                               " glyphs is in the picture: out of view, or smaller than a pixel; check "
                               "camera.position, camera.look_at, camera.fov or camera.height, and glyphs.scale "
                               "(or leave them out for automatic values)");
  const std::uint64_t untraceable = rendered.stats.untraceable_rays + rendered.shadow_stats.untraceable_rays;
  if (untraceable > 0)
    summary.warnings.push_back(std::to_string(untraceable) +
                               " rays were not traced: their coordinates are beyond the ray tracer's range "
                               "(±1.8e18, single precision); bring camera.position, render.shadow_offset and "
                               "the data's coordinates nearer the origin");
  summary.trajectories = prepared->glyphs.trajectories.size();
  summary.sources = prepared->field.sources.size();
  summary.build_seconds = build_seconds;
  summary.render_seconds = rendered.seconds;
  summary.output_seconds = seconds_since(output_start);
  summary.total_seconds = seconds_since(start);
  summary.primary_rays = rendered.primary_rays;
  summary.shadow_rays = rendered.shadow_rays;
  summary.primary_mrays_per_second = rendered.primary_mrays_per_second();
  summary.shadow_mrays_per_second = rendered.shadow_mrays_per_second();
  summary.memory_estimate = prepared->memory_estimate;
  summary.stats = rendered.stats;
  summary.shadow_stats = rendered.shadow_stats;
  return summary;
}

}  // namespace hsb
