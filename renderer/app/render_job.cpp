#include "renderer/app/render_job.h"

#include <chrono>
#include <filesystem>
#include <optional>

#include "renderer/app/batch.h"
#include "renderer/app/panel_figure.h"
#include "renderer/image/display_image.h"
#include "renderer/image/image_output.h"
#include "renderer/image/raster_stream.h"
#include "renderer/library/hyperstreamball.h"
#include "renderer/library/picture_output.h"
#include "renderer/library/pinned_scene.h"
#include "renderer/library/prepared_scene.h"

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

  const std::unique_ptr<Prepared> prepared = prepare(std::move(loaded));
  PreparedScene& scene = *prepared->scene;
  scene.output.file = file;
  const OutputSettings& output = scene.output;
  const double build_seconds = seconds_since(start);
  RenderControl control;
  control.progress = [&](double fraction) { report(JobStage::rendering, fraction); };
  // A picture with nothing drawn over it goes to its file as it is made
  // (render → display rows → file); any other is written whole after.
  std::optional<RasterStream> stream;
  if (output.streams()) {
    std::filesystem::create_directories(std::filesystem::path(image_path).parent_path());
    const bool transparent = scene.shading.background_kind == BackgroundKind::transparent;
    const RasterStream::Format format =
        display_raster_format(scene.render.width, scene.render.height, output, transparent);
    stream.emplace(image_path, format, [&, description = picture_description(scene),
                                        resolved = pinned_scene_toml(scene)] {
      return picture_metadata(scene.spec, description, resolved, prepared->color);
    });
    control.rows_done = [&, transparent, channels = format.channels, rgba = std::vector<float>()](
                            const Film& film, int first, int last) mutable {
      display_rows(film, first, last, prepared->color, transparent, rgba);
      stream->write_rows({rgba.data(), film.width(), last - first, first, 4, channels});
    };
  }
  report(JobStage::rendering, 0.0);
  Picture picture = render(*prepared, control);
  const RenderOutput& rendered = picture.rendered;

  report(JobStage::writing, 1.0);
  const auto output_start = Clock::now();
  RenderSummary summary;
  summary.warnings = picture.warnings;
  summary.render_seconds = rendered.seconds;
  summary.primary_rays = rendered.primary_rays;
  summary.shadow_rays = rendered.shadow_rays;
  summary.primary_mrays_per_second = rendered.primary_mrays_per_second();
  summary.shadow_mrays_per_second = rendered.shadow_mrays_per_second();
  summary.stats = rendered.stats;
  summary.shadow_stats = rendered.shadow_stats;
  if (stream) stream->finish();
  else write(std::move(picture), *prepared, image_path);

  summary.image_path = image_path;
  summary.trajectories = scene.glyphs.trajectories.size();
  summary.sources = scene.field.sources.size();
  summary.build_seconds = build_seconds;
  summary.output_seconds = seconds_since(output_start);
  summary.total_seconds = seconds_since(start);
  summary.memory_estimate = scene.memory_estimate;
  return summary;
}

}  // namespace hsb
