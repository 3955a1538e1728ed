#include "renderer/app/series_scale.h"

#include <cstdio>
#include <limits>

#include "field/glyph_pipeline.h"
#include "renderer/app/prepared_scene.h"
#include "renderer/image/colormap.h"
#include "renderer/scene/scene_spec.h"

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
  std::vector<double> scalars;
  GlyphMapping smallest;
  smallest.scale = std::numeric_limits<double>::infinity();
  SceneSpec first;
  for (std::size_t i = 0; i < members.size(); ++i) {
    SceneSpec spec = load_scene_or_data_file(members[i].scene, members[i].overrides);
    const GlyphScene glyphs = build_glyph_scene(spec.pipeline, glyph_extent(spec.surface));
    for (const GlyphSource& s : glyphs.sources) scalars.push_back(s.scalar);
    if (!glyphs.sources.empty() && glyphs.values.mapping.scale < smallest.scale) smallest = glyphs.values.mapping;
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
    const ColorScale scale = auto_scale(map, scalars, color.symmetric.value_or(map.diverging), color.log);
    pinned.push_back("color.range=[" + number(scale.lo) + ", " + number(scale.hi) + "]");
  }
  return pinned;
}

}  // namespace hsb
