#include "renderer/app/series_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "field/glyph_pipeline.h"
#include "renderer/image/colormap.h"
#include "renderer/library/prepared_scene.h"
#include "renderer/scene/scene_spec.h"
#include "renderer/scene/toml_text.h"

namespace hsb {
namespace {

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// Of each step's values an automatic range spans, as many as the shared
// range reads: their order statistics, evenly spaced from the least to
// the largest. Kept whole (its glyphs, 65,536 of the data's values), a
// 5,000-step series held 3 GB, and each step's reading child, a fork,
// took longer than the last. The range's fence reads the 2nd and 98th
// percentiles and the extremes, which these keep to a tenth of a per cent.
constexpr std::size_t kStepQuantiles = 1024;

// What a series' colours are chosen from: the glyphs' scalars' extremes
// (colormap_for asks only whether both signs are there) and a summary of
// the values an automatic range spans (color_range_values).
struct SeriesColors {
  std::vector<double> scalar_extremes;  // the least and largest glyph scalar so far; empty while none
  std::vector<double> reach;

  void add(const GlyphScene& glyphs) {
    for (const GlyphSource& s : glyphs.sources) {
      if (!std::isfinite(s.scalar)) continue;
      if (scalar_extremes.empty()) scalar_extremes = {s.scalar, s.scalar};
      scalar_extremes[0] = std::min(scalar_extremes[0], s.scalar);
      scalar_extremes[1] = std::max(scalar_extremes[1], s.scalar);
    }
    std::vector<double> spanned = color_range_values(glyphs);
    spanned.erase(std::remove_if(spanned.begin(), spanned.end(), [](double v) { return !std::isfinite(v); }),
                  spanned.end());
    std::sort(spanned.begin(), spanned.end());
    if (spanned.size() <= kStepQuantiles) {
      reach.insert(reach.end(), spanned.begin(), spanned.end());
      return;
    }
    for (std::size_t i = 0; i < kStepQuantiles; ++i)
      reach.push_back(spanned[i * (spanned.size() - 1) / (kStepQuantiles - 1)]);
  }
};

}  // namespace

const std::vector<std::string>& series_pinned_keys() {
  static const std::vector<std::string> keys = {
      "glyphs.scale", "glyphs.floor",  "glyphs.ceiling",  "color.map",      "color.range",  "render.width",
      "render.height", "camera.position", "camera.look_at", "camera.up", "camera.height"};
  return keys;
}

std::vector<std::string> shared_series_settings(const std::vector<SeriesMember>& members,
                                                const std::function<void(double)>& progress) {
  if (members.empty()) return {};
  SeriesColors colors;
  double smallest_scale = std::numeric_limits<double>::infinity();
  SceneSpec first;
  std::size_t largest = 0;  // the step with the largest stresses
  for (std::size_t i = 0; i < members.size(); ++i) {
    if (progress) progress(double(i) / double(members.size()));
    SceneSpec spec = load_scene_or_data_file(members[i].scene, members[i].overrides);
    // Every step's glyphs sampled on its body's lattice, none traced: the
    // same magnitudes and colours, at half the cost (most of what is left
    // is reading the file).
    const GlyphScene glyphs =
        build_glyph_scene(spec.pipeline, glyph_extent(spec.surface), {}, GlyphPlacing::on_body_lattice);
    colors.add(glyphs);
    if (!glyphs.sources.empty() && glyphs.values.mapping.scale < smallest_scale) {
      smallest_scale = glyphs.values.mapping.scale;
      largest = i;
    }
    if (i == 0) first = std::move(spec);
  }
  if (progress) progress(1.0);
  // The step with the largest stresses traced as its own picture would
  // be: its glyphs set the scale, and their colours join the range.
  GlyphMapping smallest;
  smallest.scale = std::numeric_limits<double>::infinity();
  {
    const SceneSpec spec = load_scene_or_data_file(members[largest].scene, members[largest].overrides);
    const GlyphScene glyphs = build_glyph_scene(spec.pipeline, glyph_extent(spec.surface));
    colors.add(glyphs);
    if (!glyphs.sources.empty()) smallest = glyphs.values.mapping;
  }
  std::vector<std::string> pinned;
  const GlyphSizeSpec& size = first.pipeline.size;
  if (std::isfinite(smallest.scale)) {
    if (!size.scale) pinned.push_back("glyphs.scale=" + number(smallest.scale));
    if (!size.floor) pinned.push_back("glyphs.floor=" + number(smallest.floor));
    if (!size.ceiling) pinned.push_back("glyphs.ceiling=" + number(smallest.ceiling));
  }
  const ColorSpec& color = first.color;
  const Colormap& map = colormap_for(color.map, colors.scalar_extremes, color.log);
  if (!color.map) pinned.push_back("color.map=\"" + map.name + "\"");
  if (!color.range && !colors.scalar_extremes.empty()) {
    const ColorScale scale = auto_scale(map, colors.reach, color.symmetric.value_or(map.diverging), color.log);
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
