#include "renderer/app/pinned_scene.h"

#include <sstream>

namespace hsb {
namespace {

toml::table& subtable(toml::table& root, const char* name) {
  if (!root.contains(name)) root.insert(name, toml::table{});
  return *root[name].as_table();
}

toml::array vec3(const Vec3& v) { return toml::array{v.x(), v.y(), v.z()}; }

const char* projection_name(Projection p) { return p == Projection::orthographic ? "orthographic" : "perspective"; }

}  // namespace

std::string pinned_scene_toml(const PreparedScene& p) {
  toml::table root = scene_table(p.spec);
  const auto pin = [&](bool automatic, const char* table, const char* key, auto&& value) {
    if (automatic) subtable(root, table).insert_or_assign(key, std::forward<decltype(value)>(value));
  };
  const SceneSpec& s = p.spec;
  const GlyphValues& v = p.glyphs.values;
  if (v.singular_radius) pin(!s.pipeline.data.point_load.singular_radius, "data", "singular_radius", *v.singular_radius);
  // Sources the scene gives itself (a curve, a list) have no seeds,
  // trajectories or sizes to pin.
  const bool from_data = s.pipeline.data.kind != DataKind::none;
  if (from_data && s.pipeline.seeds.automatic()) {
    toml::table& seeds = subtable(root, "seeds");
    seeds.insert_or_assign("frame", v.seeds.frame == SeedFrame::bounds ? "bounds" : "world");
    toml::array grids;
    for (const SeedGridSpec& g : v.seeds.grids)
      grids.push_back(toml::table{{"corner", vec3(g.corner)}, {"edge_u", vec3(g.edge_u)},
                                  {"edge_v", vec3(g.edge_v)}, {"n", g.n}, {"m", g.m}});
    seeds.insert_or_assign("grid", std::move(grids));
  }
  if (from_data) {
    pin(!s.pipeline.trajectory.step, "trajectories", "step", v.trajectory.step);
    pin(!s.pipeline.trajectory.max_length, "trajectories", "max_length", v.trajectory.max_length);
    pin(!s.pipeline.trajectory.min_magnitude, "trajectories", "min_magnitude", v.trajectory.min_magnitude);
    pin(!s.pipeline.spacing, "glyphs", "spacing", v.spacing);
    pin(!s.pipeline.size.scale, "glyphs", "scale", v.mapping.scale);
    pin(!s.pipeline.size.floor, "glyphs", "floor", v.mapping.floor);
    pin(!s.pipeline.size.ceiling, "glyphs", "ceiling", v.mapping.ceiling);
    pin(!s.pipeline.color, "glyphs", "color_by", color_scalar_name(p.glyphs.color));
  }
  pin(!s.color.range, "color", "range", toml::array{p.scale.lo, p.scale.hi});
  // The camera is pinned whole: position and look_at make view and frame moot.
  const bool camera_automatic = !s.camera.position || !s.camera.look_at || !s.camera.up ||
                                (s.camera.projection == Projection::orthographic && !s.camera.height);
  if (camera_automatic) {
    toml::table& camera = subtable(root, "camera");
    camera.erase("view");
    camera.erase("frame");
    camera.erase("margin");
    camera.insert_or_assign("position", vec3(p.camera.position));
    camera.insert_or_assign("look_at", vec3(p.camera.look_at));
    camera.insert_or_assign("up", vec3(p.camera.up));
    camera.insert_or_assign("projection", projection_name(p.camera.projection));
    if (p.camera.projection == Projection::orthographic) camera.insert_or_assign("height", p.camera.height);
    else camera.insert_or_assign("fov", p.camera.fov_degrees);
  }
  pin(!s.context.box, "render", "box", p.context.box.has_value());
  pin(!s.context.box_radius, "render", "box_radius", p.context.box_radius);
  pin(!s.context.shell, "render", "shell", p.context.shell != nullptr);
  pin(!s.render.shadow_offset, "render", "shadow_offset", p.render.shadow_offset);
  pin(s.context.trajectories && !s.context.trajectory_radius, "render", "trajectory_radius",
      p.context.trajectory_radius);
  pin(s.context.ground && !s.context.ground_height, "render", "ground_height", p.shading.ground_height);
  if (s.shading.ao_samples > 0 && !s.light.ao_distance) {
    toml::table& light = subtable(root, "light");
    if (!light.contains("ambient_occlusion")) light.insert("ambient_occlusion", toml::table{});
    light["ambient_occlusion"].as_table()->insert_or_assign("distance", p.shading.ao_distance);
  }
  pin(!s.render.intersector, "render", "intersector", p.trace.intersector == Intersector::exact ? "exact" : "sphere");
  pin(!s.render.min_step, "render", "min_step", p.trace.min_step);
  pin(!s.output.file, "output", "file", p.output.file);
  if (p.output.legend) pin(!s.output.colorbar_title, "output", "colorbar_title", p.output.legend->title);
  pin(!s.output.bit_depth, "output", "bit_depth", p.output.bit_depth);
  pin(!s.render.width, "render", "width", p.render.width);
  pin(!s.render.height, "render", "height", p.render.height);

  std::ostringstream out;
  out << "# " << s.path << " with every automatic value written out: save this as a scene\n"
      << "# (relative paths as in the original, so beside it) and it renders the same picture.\n"
      << "# Automatic here:";
  for (const std::string& key : p.automatic) out << " " << key;
  out << "\n" << toml::toml_formatter(root) << "\n";
  return out.str();
}

}  // namespace hsb
