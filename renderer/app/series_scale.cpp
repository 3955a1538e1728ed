#include "renderer/app/series_scale.h"

#include <cstdio>
#include <limits>

#include "field/glyph_pipeline.h"
#include "renderer/app/prepared_scene.h"
#include "renderer/image/colormap.h"
#include "renderer/scene/scene_spec.h"
#include "renderer/scene/toml_text.h"

namespace hsb {
namespace {

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

}  // namespace

std::vector<std::string> shared_series_settings(const std::vector<SeriesMember>& members) {
  if (members.empty()) return {};
  std::vector<double> scalars, reach;  // the glyphs' colour values; those the range spans
  GlyphMapping smallest;
  smallest.scale = std::numeric_limits<double>::infinity();
  SceneSpec first;
  std::size_t largest = 0;  // the step with the largest stresses
  for (std::size_t i = 0; i < members.size(); ++i) {
    SceneSpec spec = load_scene_or_data_file(members[i].scene, members[i].overrides);
    const GlyphScene glyphs = build_glyph_scene(spec.pipeline, glyph_extent(spec.surface));
    for (const GlyphSource& s : glyphs.sources) scalars.push_back(s.scalar);
    const std::vector<double> spanned = color_range_values(glyphs);
    reach.insert(reach.end(), spanned.begin(), spanned.end());
    if (!glyphs.sources.empty() && glyphs.values.mapping.scale < smallest.scale) {
      smallest = glyphs.values.mapping;
      largest = i;
    }
    if (i == 0) first = std::move(spec);
  }
  std::vector<std::string> pinned;
  const GlyphSizeSpec& size = first.pipeline.size;
  if (std::isfinite(smallest.scale)) {
    if (!size.scale) pinned.push_back("glyphs.scale=" + number(smallest.scale));
    if (!size.floor) pinned.push_back("glyphs.floor=" + number(smallest.floor));
    if (!size.ceiling) pinned.push_back("glyphs.ceiling=" + number(smallest.ceiling));
  }
  const ColorSpec& color = first.color;
  const Colormap& map = colormap_for(color.map, scalars, color.log);
  if (!color.map) pinned.push_back("color.map=\"" + map.name + "\"");
  if (!color.range && !scalars.empty()) {
    const ColorScale scale = auto_scale(map, reach, color.symmetric.value_or(map.diverging), color.log);
    pinned.push_back("color.range=[" + number(scale.lo) + ", " + number(scale.hi) + "]");
  }
  // One picture size and one camera, those of the step with the largest
  // glyphs (which frame the others'): the frames of an animation must
  // not jump or change size from step to step.
  std::vector<std::string> largest_overrides = members[largest].overrides;
  largest_overrides.insert(largest_overrides.end(), pinned.begin(), pinned.end());
  SceneSpec spec = load_scene_or_data_file(members[largest].scene, largest_overrides);
  const ColorManagement color_management = scene_color_management(spec);
  const std::unique_ptr<PreparedScene> framed = prepare_scene(std::move(spec), color_management);
  const auto pin = [&](bool given, const char* key) {
    if (const toml::node* value = framed->resolved.at_path(key).node(); value && !given)
      pinned.push_back(std::string(key) + "=" + toml_text(*value));
  };
  pin(first.render.width.has_value(), "render.width");
  pin(first.render.height.has_value(), "render.height");
  const bool camera_given = first.camera.position.has_value() || first.camera.look_at.has_value();
  for (const char* key : {"camera.position", "camera.look_at", "camera.up", "camera.height"}) pin(camera_given, key);
  return pinned;
}

}  // namespace hsb
