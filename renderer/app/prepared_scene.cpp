#include "renderer/app/prepared_scene.h"

namespace hsb {
namespace {

ColorScale color_scale(const ColorSpec& spec, const std::vector<GlyphSource>& sources) {
  const Colormap& map = colormap_named(spec.map);
  if (spec.range) return {&map, (*spec.range)[0], (*spec.range)[1]};
  std::vector<double> values;
  values.reserve(sources.size());
  for (const GlyphSource& s : sources) values.push_back(s.scalar);
  return auto_scale(map, values);
}

}  // namespace

PreparedScene prepare_scene(SceneSpec spec, const ColorManagement& color) {
  PreparedScene p;
  p.spec = std::move(spec);
  p.glyphs = build_glyph_scene(p.spec.pipeline);
  p.scale = color_scale(p.spec.color, p.glyphs.sources);
  std::vector<std::array<float, 3>> colors;
  colors.reserve(p.glyphs.sources.size());
  for (const GlyphSource& s : p.glyphs.sources) colors.push_back(color.to_scene_linear(p.scale.srgb(s.scalar)));
  p.field = make_blob_field(p.glyphs.sources, colors, p.spec.surface.influence_radius, p.spec.surface.kernel,
                            p.spec.surface.blend, p.spec.surface.isovalue);
  p.shading = p.spec.shading;
  p.shading.background = color.to_scene_linear(p.shading.background);
  p.shading.box_color = color.to_scene_linear(p.shading.box_color);
  p.shading.shell_color = color.to_scene_linear(p.shading.shell_color);
  p.camera = resolve_camera(p.spec, p.glyphs.domain);
  p.trace.intersector = p.spec.intersector;
  p.trace.min_step = p.spec.min_step * p.glyphs.domain.diagonal();
  p.trace.max_steps = p.spec.max_steps;
  return p;
}

}  // namespace hsb
