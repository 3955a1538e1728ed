#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "renderer/image/image_output.h"
#include "renderer/scene/scene_spec.h"
#include "renderer/scene/toml_reader.h"

namespace hsb {
namespace {

// Puts `value` (already parsed) at dotted `key` in `root`, creating tables.
void apply_override(toml::table& root, const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw SceneError("--set " + text + ": expected key.path=value");
  const std::string key = text.substr(0, eq), value = text.substr(eq + 1);
  const std::string where = "--set " + text;

  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value, where);
  } catch (const toml::parse_error&) {
    // Not a TOML value: take it as a bare string (file names, colormap names).
    std::ostringstream quoted;
    quoted << toml::value<std::string>(value);  // toml++ prints it as a TOML string
    parsed = toml::parse("v = " + quoted.str(), where);
  }
  toml::table* table = &root;
  std::size_t start = 0;
  for (std::size_t dot; (dot = key.find('.', start)) != std::string::npos; start = dot + 1) {
    const std::string part = key.substr(start, dot - start);
    if (!table->contains(part)) table->insert(part, toml::table{});
    table = (*table)[part].as_table();
    if (!table) throw SceneError(where + ": " + key.substr(0, dot) + " is not a table");
  }
  const std::string leaf = key.substr(start);
  if (leaf.empty()) throw SceneError(where + ": expected key.path=value");
  // Moved, not copied: toml++ keeps a node's source region only on moves, and
  // that region is what error messages point at.
  parsed.get("v")->visit([&](auto&& node) { table->insert_or_assign(leaf, std::move(node)); });
}

void read_data(TableReader& data, DataSpec& spec, const std::string& scene_path) {
  spec.kind = data.choice("kind", DataKind::point_load,
                          {{"point_load", DataKind::point_load}, {"vtk", DataKind::vtk_file}});
  if (spec.kind == DataKind::vtk_file) {
    const std::string file = data.string("file", "");
    if (file.empty()) data.fail_at("file", "is required when data.kind = \"vtk\" (a .vtk, .vti, .vtu, .vts or .vtr file)");
    // Relative to the scene file, so scenes can be run from anywhere.
    const std::filesystem::path p(file);
    spec.file.path = p.is_absolute() ? file : (std::filesystem::path(scene_path).parent_path() / p).lexically_normal().string();
    if (!std::filesystem::is_regular_file(spec.file.path))
      data.fail_at("file", "names no file: " + spec.file.path + " (relative paths are relative to the scene file)");
    spec.file.array = data.string("array", "");
    spec.file.association = data.choice("association", TensorAssociation::automatic,
                                        {{"auto", TensorAssociation::automatic},
                                         {"point", TensorAssociation::point},
                                         {"cell", TensorAssociation::cell}});
    spec.file.cell_tensors = data.choice("cell_tensors", CellTensors::constant,
                                         {{"constant", CellTensors::constant},
                                          {"averaged", CellTensors::averaged}});
  }
  PointLoadSpec& load = spec.point_load;
  if (const std::vector<double> b = data.numbers("bounds", 6); !b.empty()) {
    load.bounds = Box3{Vec3(b[0], b[2], b[4]), Vec3(b[1], b[3], b[5])};
    if (!(load.bounds.size().array() > 0.0).all())
      data.fail_at("bounds", "must be [xmin, xmax, ymin, ymax, zmin, zmax] with min < max");
  }
  load.load = data.number("load", load.load);
  load.poisson_ratio = data.number("poisson_ratio", load.poisson_ratio, {-1.0, 0.5, false});
  load.singular_radius = data.number("singular_radius", 0.0, non_negative);
  if (const std::vector<double> g = data.numbers("sample_grid", 3); !g.empty()) {
    for (int k = 0; k < 3; ++k) spec.sample_grid[k] = int(g[k]);
    const bool off = spec.sample_grid == std::array<int, 3>{0, 0, 0};
    const bool valid = std::all_of(g.begin(), g.end(), [](double v) { return v >= 2 && v == std::floor(v); });
    if (!off && !valid)
      data.fail_at("sample_grid", "must be three integers >= 2 (or [0, 0, 0] for none)");
  }
  data.finish();
}

void read_seeds(TableReader& seeds, GlyphPipelineSpec& spec) {
  spec.seed_frame = seeds.choice("frame", SeedFrame::world,
                                 {{"world", SeedFrame::world}, {"bounds", SeedFrame::bounds}});
  spec.seed_points = seeds.points("points");
  for (TableReader& grid : seeds.tables("grid")) {
    SeedGridSpec g;
    g.corner = grid.vec3("corner", g.corner);
    g.edge_u = grid.vec3("edge_u", g.edge_u);
    g.edge_v = grid.vec3("edge_v", g.edge_v);
    g.n = grid.integer("n", g.n, 1, 10000);
    g.m = grid.integer("m", g.m, 1, 10000);
    grid.finish();
    spec.seed_grids.push_back(g);
  }
  seeds.finish();
}

void read_trajectories(TableReader& t, TrajectoryOptions& options) {
  options.family = t.choice("family", EigenFamily::major,
                            {{"major", EigenFamily::major}, {"medium", EigenFamily::medium},
                             {"minor", EigenFamily::minor}});
  // Absent means automatic (0 here, resolved against the data's size).
  options.step = t.number("step", options.step, positive);
  options.max_length = t.number("max_length", options.max_length, positive);
  options.degeneracy_tolerance = t.number("degeneracy", options.degeneracy_tolerance, non_negative);
  options.min_magnitude = t.number("min_magnitude", options.min_magnitude, non_negative);
  options.max_steps = t.integer("max_steps", options.max_steps, 1);
  t.finish();
}

void read_glyphs(TableReader& g, GlyphPipelineSpec& spec) {
  spec.placement = g.choice("placement", SourcePlacement::along_trajectories,
                            {{"trajectories", SourcePlacement::along_trajectories},
                             {"seeds", SourcePlacement::at_seeds}});
  spec.spacing = g.number("spacing", spec.spacing, positive);  // absent: automatic
  GlyphMapping& m = spec.mapping;
  m.mapping = g.choice("mapping", RadiusMapping::linear,
                       {{"linear", RadiusMapping::linear}, {"sqrt", RadiusMapping::sqrt},
                        {"normalized", RadiusMapping::normalized},
                        {"constant", RadiusMapping::constant}});
  m.scale = g.number("scale", m.scale, positive);
  m.floor = g.number("floor", m.floor, positive);
  m.ceiling = g.number("ceiling", m.ceiling, positive_or_infinite);
  spec.color = g.choice("color_by", ColorScalar::lambda3,
                        {{"lambda1", ColorScalar::lambda1}, {"lambda2", ColorScalar::lambda2},
                         {"lambda3", ColorScalar::lambda3}, {"mean", ColorScalar::mean},
                         {"von_mises", ColorScalar::von_mises}});
  g.finish();
  if (m.ceiling < m.floor)
    g.fail_at("ceiling", "must be >= glyphs.floor");
}

void read_surface(TableReader& s, SurfaceSpec& spec) {
  spec.kernel = s.choice("kernel", KernelKind::wyvill,
                         {{"wyvill", KernelKind::wyvill}, {"quartic", KernelKind::quartic},
                          {"blinn", KernelKind::blinn}});
  spec.blend = s.choice("blend", Blend::sum, {{"sum", Blend::sum}, {"max", Blend::max}});
  spec.influence_radius = s.number("influence_radius", spec.influence_radius, positive);
  spec.isovalue = s.number("isovalue", spec.isovalue, {0.0, 1.0, true});
  s.finish();
}

void read_color(TableReader& c, ColorSpec& spec) {
  spec.map = c.choice<std::string>("map", "viridis", {{"viridis", "viridis"}, {"coolwarm", "coolwarm"}});
  if (const std::vector<double> r = c.numbers("range", 2); !r.empty()) {
    if (!(r[1] > r[0])) c.fail_at("range", "must be [low, high] with low < high");
    spec.range = std::array<double, 2>{r[0], r[1]};
  }
  c.finish();
}

void read_camera(TableReader& c, SceneSpec& spec) {
  if (c.has("look_at")) spec.camera_look_at = c.vec3("look_at", Vec3::Zero());
  if (c.has("position")) spec.camera_position = c.vec3("position", Vec3::Zero());
  c.vec3("look_at", Vec3::Zero());  // known keys even when absent
  c.vec3("position", Vec3::Zero());
  spec.camera.up = c.vec3("up", spec.camera.up);
  spec.camera.fov_degrees = c.number("fov", spec.camera.fov_degrees, {0.0, 179.0, true});
  c.finish();
  if (spec.camera_position && spec.camera_look_at && (*spec.camera_position - *spec.camera_look_at).norm() == 0.0)
    c.fail_at("position", "must differ from camera.look_at");
  if (spec.camera.up.norm() == 0.0) c.fail_at("up", "must not be zero");
}

void read_light(TableReader& l, ShadingSpec& spec) {
  spec.light_from = l.vec3("from", spec.light_from);
  if (spec.light_from.norm() == 0.0) l.fail_at("from", "must not be zero");
  spec.light_color = l.color("color", spec.light_color);
  spec.light_intensity = l.number("intensity", spec.light_intensity, non_negative);
  spec.ambient = l.number("ambient", spec.ambient, non_negative);
  spec.shadows = l.boolean("shadows", spec.shadows);
  spec.specular = l.number("specular", spec.specular, non_negative);
  spec.shininess = l.number("shininess", spec.shininess, positive);
  l.finish();
}

void read_render(TableReader& r, SceneSpec& spec) {
  spec.render.width = r.integer("width", spec.render.width, 1, 16384);
  spec.render.height = r.integer("height", spec.render.height, 1, 16384);
  spec.render.samples = r.integer("samples", spec.render.samples, 1, 16);
  spec.render.shadow_offset = r.number("shadow_offset", spec.render.shadow_offset, non_negative);
  spec.shading.background = r.color("background", spec.shading.background);
  spec.shading.box = r.boolean("box", spec.shading.box);
  spec.shading.box_color = r.color("box_color", spec.shading.box_color);
  spec.shading.box_radius = r.number("box_radius", spec.shading.box_radius, non_negative);
  spec.shading.shell = r.boolean("shell", spec.shading.shell);
  spec.shading.shell_color = r.color("shell_color", spec.shading.shell_color);
  spec.shading.shell_opacity = r.number("shell_opacity", spec.shading.shell_opacity, {0.0, 1.0, false});
  spec.shading.shell_edge_opacity =
      r.number("shell_edge_opacity", spec.shading.shell_edge_opacity, {0.0, 1.0, false});
  spec.intersector = r.choice("intersector", spec.intersector,
                              {{"sphere", Intersector::sphere}, {"exact", Intersector::exact}});
  if (spec.intersector == Intersector::exact && !exact_crossing_supported(spec.surface.kernel, spec.surface.blend))
    r.fail_at("intersector", "= \"exact\" needs surface.kernel \"wyvill\" or \"quartic\" (or surface.blend = \"max\"): "
                             "blinn's exponential is not a polynomial along a ray");
  spec.min_step = r.number("min_step", spec.min_step, positive);
  spec.max_steps = r.integer("max_steps", spec.max_steps, 1);
  r.finish();
}

void read_output(TableReader& o, OutputSpec& spec) {
  spec.file = o.string("file", spec.file);
  if (!is_supported_image_path(spec.file))
    o.fail_at("file", "must end in .png, .tif, .tiff or .exr, got \"" + spec.file + "\"");
  spec.bit_depth = o.integer("bit_depth", spec.bit_depth, 8, 16);
  if (spec.bit_depth != 8 && spec.bit_depth != 16)
    o.fail_at("bit_depth", "must be 8 or 16");
  spec.display = o.string("display", spec.display);
  spec.view = o.string("view", spec.view);
  spec.colorbar = o.boolean("colorbar", spec.colorbar);
  spec.colorbar_title = o.string("colorbar_title", spec.colorbar_title);
  o.finish();
}

}  // namespace

CameraSpec resolve_camera(const SceneSpec& spec, const Box3& domain) {
  CameraSpec camera = spec.camera;
  camera.look_at = spec.camera_look_at.value_or(domain.centre());
  camera.position = spec.camera_position.value_or(domain.centre() + domain.diagonal() * Vec3(0.95, -1.45, 0.75));
  if ((camera.look_at - camera.position).cross(camera.up).norm() < 1e-12 * domain.diagonal())
    throw SceneError(spec.path + ": camera.up must not be parallel to the viewing direction");
  return camera;
}

std::string scene_fingerprint_text(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  for (const std::string& o : overrides) text << "\n--set " << o;
  return text.str();
}

SceneSpec load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  if (!std::filesystem::is_regular_file(path)) throw SceneError(path + ": no such scene file");
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source();
    throw SceneError(path + ":" + std::to_string(where.begin.line) + ":" +
                     std::to_string(where.begin.column) + ": " + std::string(e.description()));
  }
  for (const std::string& o : overrides) apply_override(root, o);

  SceneSpec spec;
  spec.path = path;
  TableReader top(root, "", path);
  // Automatic lengths (0) are resolved once the data set's size is known.
  spec.pipeline.trajectory.step = 0.0;
  spec.pipeline.trajectory.max_length = 0.0;
  spec.pipeline.spacing = 0.0;
  if (auto data = top.table("data")) read_data(*data, spec.pipeline.data, path);
  // A box of edges frames an analytic domain; a mesh is shown by its shell.
  const bool mesh = spec.pipeline.data.kind == DataKind::vtk_file;
  spec.shading.box = !mesh;
  spec.shading.shell = mesh;

  if (auto seeds = top.table("seeds")) read_seeds(*seeds, spec.pipeline);
  if (auto t = top.table("trajectories")) read_trajectories(*t, spec.pipeline.trajectory);
  if (auto g = top.table("glyphs")) read_glyphs(*g, spec.pipeline);
  if (auto s = top.table("surface")) read_surface(*s, spec.surface);
  if (auto c = top.table("color")) read_color(*c, spec.color);
  if (auto c = top.table("camera")) read_camera(*c, spec);
  if (auto l = top.table("light")) read_light(*l, spec.shading);
  // Exact wherever it applies: it was the faster of the two over the figure
  // scenes, and exact; blinn summed has no polynomial form, so it is traced.
  spec.intersector = exact_crossing_supported(spec.surface.kernel, spec.surface.blend) ? Intersector::exact
                                                                                        : Intersector::sphere;
  if (auto r = top.table("render")) read_render(*r, spec);
  spec.output.file = std::filesystem::path(path).stem().string() + ".png";
  if (auto o = top.table("output")) read_output(*o, spec.output);
  top.finish();

  return spec;
}

}  // namespace hsb
