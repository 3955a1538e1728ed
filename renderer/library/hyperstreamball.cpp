#include "renderer/library/hyperstreamball.h"

#include <cstdint>

#include "renderer/image/display_image.h"
#include "renderer/image/image_output.h"
#include "renderer/library/picture_output.h"
#include "renderer/library/pinned_scene.h"
#include "renderer/render/ray_scene.h"

namespace hsb {
namespace {

// What a finished render says about itself: a picture without the glyphs
// it was asked for is no success, and rays beyond single precision were
// not traced.
std::vector<std::string> picture_warnings(const PreparedScene& p, const RenderOutput& rendered) {
  std::vector<std::string> warnings = p.warnings;
  if (p.context.glyphs && !p.field.sources.empty() && rendered.stats.glyph_hits == 0)
    warnings.push_back("none of the " + std::to_string(p.field.sources.size()) +
                       " glyphs is in the picture: out of view, or smaller than a pixel; check "
                       "camera.position, camera.look_at, camera.fov or camera.height, and glyphs.scale "
                       "(or leave them out for automatic values)");
  const std::uint64_t untraceable = rendered.stats.untraceable_rays + rendered.shadow_stats.untraceable_rays;
  if (untraceable > 0)
    warnings.push_back(std::to_string(untraceable) +
                       " rays were not traced: their coordinates are beyond the ray tracer's range "
                       "(±1.8e18, single precision); bring camera.position, render.shadow_offset and "
                       "the data's coordinates nearer the origin");
  return warnings;
}

bool transparent(const PreparedScene& p) { return p.shading.background_kind == BackgroundKind::transparent; }

}  // namespace

SceneSpec load(const std::string& path, const std::vector<std::string>& overrides) {
  return load_scene_or_data_file(path, overrides);
}

SceneSpec load_text(const std::string& text, const std::string& name, const std::string& base_dir,
                    const std::vector<std::string>& overrides) {
  return load_scene_text(text, name, base_dir, overrides);
}

std::unique_ptr<Prepared> prepare(SceneSpec spec) {
  ColorManagement color = scene_color_management(spec);
  std::unique_ptr<PreparedScene> scene = prepare_scene(std::move(spec), color);
  return std::unique_ptr<Prepared>(new Prepared{std::move(color), std::move(scene)});
}

Picture render(const Prepared& prepared, const RenderControl& control) { return render(*prepared.scene, control); }

Picture render(const PreparedScene& p, const RenderControl& control) {
  // One Embree device for the process: it holds the threads' state.
  static const EmbreeDevice device;
  const RayScene scene(device, p.field, p.trace, p.context);
  RenderSettings settings = p.render;
  settings.cancel = control.cancel;
  settings.progress = control.progress;
  settings.rows_done = control.rows_done;
  Picture picture{render_image(scene, p.camera, p.shading, settings), {}};
  picture.warnings = picture_warnings(p, picture.rendered);
  return picture;
}

std::vector<float> display_rgba(const Picture& picture, const Prepared& prepared) {
  Film film = picture.rendered.film;
  return display_pixels(std::move(film), prepared.color, transparent(*prepared.scene));
}

void write(Picture picture, const Prepared& prepared, const std::string& path) {
  const PreparedScene& p = *prepared.scene;
  auto metadata = picture_metadata(p.spec, picture_description(p), pinned_scene_toml(p), prepared.color);
  if (is_scene_linear_format(path)) {
    write_scene_linear_picture(path, picture.rendered.film, p.output, std::move(metadata));
    return;
  }
  const int width = picture.rendered.film.width(), height = picture.rendered.film.height();
  std::vector<float> rgba = display_pixels(std::move(picture.rendered.film), prepared.color, transparent(p));
  picture.rendered.film = Film(1, 1);  // the rest of its memory is no longer needed
  Annotations annotations;
  if (p.output.legend)
    annotations.legends.push_back({*p.output.legend, p.scale, legend_ink(rgba, width, height, *p.output.legend)});
  write_display_picture(path, std::move(rgba), width, height, transparent(p), annotations, p.output,
                        std::move(metadata), prepared.color);
}

}  // namespace hsb
