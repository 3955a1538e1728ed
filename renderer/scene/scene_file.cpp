#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/input_file.h"
#include "field/reading/component_order.h"
#include "field/reading/data_formats.h"
#include "renderer/image/colormap.h"
#include "renderer/image/image_output.h"
#include "renderer/scene/scene_keys.h"
#include "renderer/scene/scene_spec.h"
#include "renderer/scene/toml_reader.h"
#include "renderer/scene/toml_text.h"

namespace hsb {
namespace {

// Puts `value` (already parsed) at dotted `key` in `root`, creating tables.
void apply_override(toml::table& root, const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw SceneError("--set " + text + ": expected key.path=value");
  const std::string key = text.substr(0, eq), value = text.substr(eq + 1);
  const std::string where = "--set " + text;
  if (!find_scene_key(key) && !is_scene_table(key))
    throw SceneError(where + ": " + key + " is not a scene key" + nearest_key_hint(key) +
                     " (hsb keys lists them all)");

  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value, where);
  } catch (const toml::parse_error&) {
    // Not a TOML value: take it as a bare string (file names, colormap names).
    std::ostringstream quoted;
    quoted << toml::value<std::string>(value);  // toml++ prints it as a TOML string
    parsed = toml::parse("v = " + quoted.str(), where);
  }
  const std::size_t dot = key.rfind('.');
  if (dot != std::string::npos && !table_at_path(root, key.substr(0, dot)))
    throw SceneError(where + ": " + key.substr(0, dot) + " is not a table");
  parsed.get("v")->visit([&](auto&& node) { assign_at_path(root, key, std::move(node)); });
}

// Keys of one data kind, refused in a table of the other: a scene that
// gives a point load's bounds for a mesh has a mistake in it.
void refuse_keys(TableReader& data, std::initializer_list<const char*> keys, const char* kind) {
  for (const char* key : keys)
    if (data.has(key)) data.fail_at(key, std::string("applies only to data.kind = \"") + kind + "\"");
}

// `file`, relative to the scene file unless absolute, and an error at
// `key` unless it names a file.
std::string existing_file(TableReader& table, std::string_view key, const std::string& file,
                          const std::string& base_dir) {
  const std::filesystem::path p(file);
  const std::string path = p.is_absolute() ? file : (std::filesystem::path(base_dir) / p).lexically_normal().string();
  if (const std::string why = unreadable_input(path); !why.empty())
    table.fail_at(key, "names " + path + ": " + why +
                           (why == "no such file" ? " (relative paths are relative to the scene file)" : ""));
  return path;
}

void read_data(TableReader& data, DataSpec& spec, const std::string& base_dir) {
  // A file means VTK data unless the scene says otherwise.
  const std::optional<std::string> file = data.optional_string("file");
  spec.kind = data.choice("kind", file ? DataKind::vtk_file : DataKind::point_load,
                          {{"point_load", DataKind::point_load}, {"vtk", DataKind::vtk_file}});
  spec.sign = data.choice<SignConvention>("sign", {{"tension-positive", SignConvention::tension_positive},
                                                   {"compression-positive", SignConvention::compression_positive}});
  if (spec.kind == DataKind::vtk_file) {
    if (!file || file->empty())
      data.fail_at("file", "is required when data.kind = \"vtk\" (a file of " + readable_formats_text() + ")");
    // Relative to the scene file, so scenes can be run from anywhere.
    spec.file.path = existing_file(data, "file", *file, base_dir);
    if (const std::string why = unreadable_format_message(spec.file.path); !why.empty())
      data.fail_at("file", "names " + why);
    spec.file.array = data.string("array");
    if (data.has("quantity"))
      spec.quantity = data.choice<DataQuantity>("quantity", {{"stress", DataQuantity::stress},
                                                            {"diffusion", DataQuantity::diffusion}});
    spec.file.kind = data.choice<FieldKind>("field", {{"auto", FieldKind::automatic}, {"tensor", FieldKind::tensor},
                                           {"vector", FieldKind::vector}});
    spec.file.association = data.choice<TensorAssociation>("association", {{"auto", TensorAssociation::automatic},
                                                        {"point", TensorAssociation::point},
                                                        {"cell", TensorAssociation::cell}});
    spec.file.step = data.optional_integer("step").value_or(-1);
    spec.file.block = data.string("block");
    std::vector<std::pair<std::string, std::string>> orders;
    for (const ComponentOrder& o : component_orders()) orders.emplace_back(o.name, o.name);
    // Absent: the order the file records, else VTK's (field/reading/vtk_data.h).
    if (data.has("components")) spec.file.components = data.choice<std::string>("components", orders);
    if (data.has("frame"))
      spec.file.frame = data.choice<TensorFrame>("frame", {{"world", TensorFrame::world},
                                                           {"voxel", TensorFrame::voxel},
                                                           {"fsl", TensorFrame::fsl}});
    spec.file.cell_tensors =
        data.choice<CellTensors>("cell_tensors", {{"constant", CellTensors::constant}, {"averaged", CellTensors::averaged}});
    refuse_keys(data, {"bounds", "load", "poisson_ratio", "singular_radius"}, "point_load");
  } else {
    if (file) data.fail_at("file", "applies only to data.kind = \"vtk\"");
    refuse_keys(data, {"array", "association", "block", "cell_tensors", "components", "field", "frame", "quantity", "step"},
                "vtk");
    PointLoadSpec& load = spec.point_load;
    const std::vector<double> b = data.numbers("bounds");
    load.bounds = Box3{Vec3(b[0], b[2], b[4]), Vec3(b[1], b[3], b[5])};
    if (!(load.bounds.size().array() > 0.0).all())
      data.fail_at("bounds", "must be [xmin, xmax, ymin, ymax, zmin, zmax] with min < max");
    load.load = data.number("load");
    load.poisson_ratio = data.number("poisson_ratio");
    load.singular_radius = data.optional_number("singular_radius");
  }
  const std::vector<double> g = data.numbers("sample_grid");
  for (int k = 0; k < 3; ++k) spec.sample_grid[std::size_t(k)] = int(g[std::size_t(k)]);
  const bool off = spec.sample_grid == std::array<int, 3>{0, 0, 0};
  const bool valid = std::all_of(g.begin(), g.end(), [](double v) { return v >= 2 && v == std::floor(v); });
  if (!off && !valid) data.fail_at("sample_grid", "must be three integers in [2, 1000] (or [0, 0, 0] for none)");
  data.finish();
}

void read_seeds(TableReader& seeds, SeedSpec& spec) {
  if (seeds.has("strategy"))
    spec.strategy = seeds.choice<SeedStrategy>(
        "strategy", {{"even", SeedStrategy::even}, {"grid", SeedStrategy::grid}, {"points", SeedStrategy::points}});
  spec.separation = seeds.optional_number("separation");
  spec.importance = seeds.optional_boolean("importance");
  spec.frame = seeds.choice<SeedFrame>("frame", {{"world", SeedFrame::world}, {"bounds", SeedFrame::bounds}});
  spec.points = seeds.points("points");
  for (TableReader& grid : seeds.tables("grid")) {
    SeedGridSpec g;
    g.corner = grid.vector("corner");
    g.edge_u = grid.vector("edge_u");
    g.edge_v = grid.vector("edge_v");
    g.n = grid.integer("n");
    g.m = grid.integer("m");
    grid.finish();
    spec.grids.push_back(g);
  }
  const SeedStrategy strategy = spec.resolved_strategy();
  if (strategy == SeedStrategy::points && spec.points.empty() && spec.grids.empty())
    seeds.fail_at("strategy", "= \"points\" needs seeds.points or [[seeds.grid]]");
  if (strategy != SeedStrategy::even)
    for (const char* key : {"separation", "importance"})
      if (seeds.has(key)) seeds.fail_at(key, "applies only to seeds.strategy = \"even\"");
  seeds.finish();
}

void read_region(TableReader& r, GlyphPipelineSpec& pipeline, const std::string& base_dir) {
  RegionSpec& spec = pipeline.region;
  std::vector<std::pair<std::string, ColorScalar>> names;
  for (ColorScalar c : named_color_scalars())
    if (is_tensor_measure(c)) names.emplace_back(color_scalar_name(c), c);
  spec.measure = r.choice("measure", names);
  spec.above = r.optional_number("above");
  if (const std::optional<std::string> mask = r.optional_string("mask")) {
    if (pipeline.data.kind != DataKind::vtk_file)
      r.fail_at("mask", "needs data.file: the point load has no mask");
    const std::string prefix = RegionSpec::kMaskArrayPrefix;
    if (mask->rfind(prefix, 0) == 0) {
      // A scalar array of the data file, read with it.
      spec.mask = *mask;
      pipeline.data.file.mask_array = mask->substr(prefix.size());
      if (pipeline.data.file.mask_array.empty())
        r.fail_at("mask", "= \"array:NAME\" needs the array's name after the colon");
    } else {
      spec.mask = existing_file(r, "mask", *mask, base_dir);
      if (const std::string why = unreadable_format_message(spec.mask); !why.empty()) r.fail_at("mask", "names " + why);
    }
  }
  r.finish();
}

void read_trajectories(TableReader& t, TrajectorySpec& spec) {
  if (t.has("family"))
    spec.families = t.choice<std::vector<EigenFamily>>(
        "family", {{"major", {EigenFamily::major}}, {"medium", {EigenFamily::medium}}, {"minor", {EigenFamily::minor}},
                   {"major+minor", {EigenFamily::major, EigenFamily::minor}}});
  spec.step = t.optional_number("step");
  spec.max_length = t.optional_number("max_length");
  spec.degeneracy_tolerance = t.number("degeneracy");
  spec.min_magnitude = t.optional_number("min_magnitude");
  spec.max_steps = t.integer("max_steps");
  spec.direction = t.choice<TraceDirection>("direction", {{"both", TraceDirection::both}, {"forward", TraceDirection::forward},
                                          {"backward", TraceDirection::backward}});
  spec.max_turn = t.optional_number("max_turn");
  spec.stop_below = t.optional_number("stop_below");
  spec.tensorlines = t.choice<bool>("method", {{"eigenvector", false}, {"tensorlines", true}});
  spec.puncture = t.number("puncture");
  if (spec.tensorlines && !spec.families.empty() &&
      (spec.families.size() != 1 || spec.families.front() != EigenFamily::major))
    t.fail_at("method", "= \"tensorlines\" follows the major eigenvector only; trajectories.family must be \"major\" or left out");
  t.finish();
}

void read_curve(TableReader& c, CurveSpec& spec) {
  spec.kind = c.choice<CurveKind>("kind", {{"line", CurveKind::line}, {"circle", CurveKind::circle}, {"helix", CurveKind::helix},
                                {"polyline", CurveKind::polyline}});
  const auto only_for = [&](std::initializer_list<const char*> keys, std::initializer_list<CurveKind> kinds,
                            const char* which) {
    if (std::find(kinds.begin(), kinds.end(), spec.kind) != kinds.end()) return;
    for (const char* key : keys)
      if (c.has(key)) c.fail_at(key, std::string("applies only to glyphs.curve.kind ") + which);
  };
  only_for({"from", "to"}, {CurveKind::line}, "\"line\"");
  only_for({"centre", "radius", "axis"}, {CurveKind::circle, CurveKind::helix}, "\"circle\" or \"helix\"");
  only_for({"pitch", "turns"}, {CurveKind::helix}, "\"helix\"");
  only_for({"points"}, {CurveKind::polyline}, "\"polyline\"");
  spec.from = c.vector("from");
  spec.to = c.vector("to");
  if (spec.kind == CurveKind::line && spec.from == spec.to) c.fail_at("to", "must differ from glyphs.curve.from");
  spec.centre = c.vector("centre");
  spec.radius = c.number("radius");
  spec.axis = c.vector("axis");
  spec.pitch = c.number("pitch");
  spec.turns = c.number("turns");
  spec.points = c.points("points");
  if (spec.kind == CurveKind::polyline && spec.points.size() < 2)
    c.fail_at(c.has("points") ? "points" : "kind", "needs glyphs.curve.points: at least two [x, y, z]");
  spec.count = c.integer("count");
  const std::vector<double> semi_axes = c.numbers("semi_axes");
  spec.semi_axes = Vec3(semi_axes[0], semi_axes[1], semi_axes[2]);
  c.finish();
}

void read_glyphs(TableReader& g, GlyphPipelineSpec& spec, SurfaceSpec& surface, const std::string& base_dir) {
  spec.placement = g.choice<SourcePlacement>("placement", {{"trajectories", SourcePlacement::along_trajectories},
                                          {"seeds", SourcePlacement::at_seeds},
                                          {"points", SourcePlacement::at_data_points},
                                          {"curve", SourcePlacement::curve},
                                          {"list", SourcePlacement::list}});
  TableReader curve = g.table("curve");
  if (g.has("curve") && spec.placement != SourcePlacement::curve)
    curve.fail_at("kind", "[glyphs.curve] needs glyphs.placement = \"curve\"");
  read_curve(curve, spec.curve);
  if (const std::optional<std::string> file = g.optional_string("file")) {
    if (spec.placement != SourcePlacement::list) g.fail_at("file", "applies only to glyphs.placement = \"list\"");
    spec.list_file = existing_file(g, "file", *file, base_dir);
  } else if (spec.placement == SourcePlacement::list) {
    g.fail_at("placement", "= \"list\" needs glyphs.file, a CSV file of sources");
  }
  surface.shape_given = g.has("shape");
  surface.shape = g.choice<GlyphShape>("shape", GlyphShape::ellipsoid,
                                       {{"ellipsoid", GlyphShape::ellipsoid},
                                        {"superquadric", GlyphShape::superquadric},
                                        {"signed", GlyphShape::signed_superquadric}});
  if (g.has("sharpness") && surface.shape == GlyphShape::ellipsoid)
    g.fail_at("sharpness", "applies only to glyphs.shape = \"superquadric\" or \"signed\"");
  surface.sharpness = g.number("sharpness");
  spec.stretch = g.number("stretch");
  spec.thickness = g.optional_number("thickness");
  spec.spacing = g.optional_number("spacing");
  spec.beads = g.optional_number("beads");
  if (spec.beads && spec.spacing)
    g.fail_at("beads", "places the glyphs end to end, so glyphs.spacing has no use beside it: give one of the two");
  if (spec.beads && spec.placement != SourcePlacement::along_trajectories)
    g.fail_at("beads", "applies only to glyphs.placement = \"trajectories\"");
  spec.signed_shapes = surface.shape == GlyphShape::signed_superquadric;
  spec.stride = g.optional_integer("stride");
  GlyphSizeSpec& size = spec.size;
  size.mapping = g.choice<RadiusMapping>("mapping", {{"linear", RadiusMapping::linear}, {"sqrt", RadiusMapping::sqrt},
                                      {"normalized", RadiusMapping::normalized},
                                      {"constant", RadiusMapping::constant}});
  size.scale = g.optional_number("scale");
  size.floor = g.optional_number("floor");
  size.ceiling = g.optional_number("ceiling");
  // "array:NAME": a scalar array of the data file.
  const std::string array_prefix = "array:";
  if (g.holds_string("color_by") && g.string("color_by").rfind(array_prefix, 0) == 0) {
    const std::string name = g.string("color_by").substr(array_prefix.size());
    if (name.empty()) g.fail_at("color_by", "= \"array:NAME\" needs the array's name after the colon");
    spec.color = ColorScalar::array;
    spec.data.file.color_array = name;
  } else if (g.has("color_by")) {
    std::vector<std::pair<std::string, ColorScalar>> names;
    for (ColorScalar c : named_color_scalars()) names.emplace_back(color_scalar_name(c), c);
    spec.color = g.choice("color_by", names);
  }
  g.finish();
  if (size.floor && size.ceiling && *size.ceiling < *size.floor) g.fail_at("ceiling", "must be >= glyphs.floor");
}

void read_surface(TableReader& s, SurfaceSpec& spec) {
  std::vector<std::pair<std::string, KernelKind>> kernels;
  for (const KernelTraits& k : all_kernel_traits()) kernels.emplace_back(k.name, k.kind);
  spec.kernel = s.choice("kernel", kernels);
  spec.blend = s.choice<Blend>("blend", {{"sum", Blend::sum}, {"max", Blend::max}});
  spec.influence_radius = s.number("influence_radius");
  spec.isovalue = s.number("isovalue");
  s.finish();
}

void read_color(TableReader& c, ColorSpec& spec) {
  std::vector<std::pair<std::string, std::string>> maps;
  for (const std::string& name : colormap_names()) maps.emplace_back(name, name);
  if (c.has("map")) spec.map = c.choice<std::string>("map", maps);
  spec.log = c.choice<bool>("scale", {{"linear", false}, {"log", true}});
  spec.symmetric = c.optional_boolean("symmetric");
  if (spec.log && spec.symmetric.value_or(false)) c.fail_at("symmetric", "cannot be true with color.scale = \"log\"");
  if (const std::vector<double> r = c.numbers("range"); !r.empty()) {
    if (!(r[1] > r[0])) c.fail_at("range", "must be [low, high] with low < high");
    if (spec.log && !(r[0] > 0.0)) c.fail_at("range", "must be above zero with color.scale = \"log\"");
    spec.range = std::array<double, 2>{r[0], r[1]};
  }
  c.finish();
}

void read_camera(TableReader& c, CameraRequest& spec) {
  spec.position = c.optional_vector("position");
  spec.look_at = c.optional_vector("look_at");
  spec.up = c.optional_vector("up");
  // A named view, or the direction from the scene towards the camera.
  if (c.holds_string("view")) {
    const std::string name = c.string("view");
    const std::optional<Vec3> v = named_view(name);
    if (!v) {
      std::string names;
      for (const std::string& n : scene_key("camera.view").choices) names += (names.empty() ? "\"" : ", \"") + n + "\"";
      c.fail_at("view", "must be one of " + names + " or a direction [x, y, z], got string \"" + name + "\"");
    }
    spec.view = *v;
  } else if (const std::optional<Vec3> v = c.optional_vector("view")) {
    if (v->norm() == 0.0) c.fail_at("view", "must not be zero");
    spec.view = v->normalized();
  }
  spec.projection =
      c.choice<Projection>("projection", {{"perspective", Projection::perspective}, {"orthographic", Projection::orthographic}});
  spec.fov_degrees = c.number("fov");
  spec.height = c.optional_number("height");
  spec.frame = c.choice<FrameTarget>("frame", {{"drawn", FrameTarget::drawn}, {"glyphs", FrameTarget::glyphs}, {"data", FrameTarget::data}});
  spec.margin = c.number("margin");
  c.finish();
  if (spec.position && spec.look_at && (*spec.position - *spec.look_at).norm() == 0.0)
    c.fail_at("position", "must differ from camera.look_at");
  const std::optional<Vec3> view =
      spec.position && spec.look_at ? std::optional<Vec3>(*spec.position - *spec.look_at) : spec.view;
  if (spec.up && view && view->cross(*spec.up).norm() < 1e-9 * view->norm() * spec.up->norm())
    c.fail_at("up", "must not be parallel to the viewing direction");
}

void read_light(TableReader& l, ShadingSpec& spec, LightLengths& lengths) {
  spec.light_from = l.vector("from");
  spec.light_color = l.color("color");
  spec.light_intensity = l.number("intensity");
  spec.light_size = l.number("size");
  spec.light_samples = l.integer("samples");
  spec.shadows = l.boolean("shadows");
  spec.fill_from = l.vector("fill_from");
  spec.fill_intensity = l.number("fill");
  spec.ambient = l.number("ambient");
  spec.specular = l.number("specular");
  spec.shininess = l.number("shininess");
  TableReader ao = l.table("ambient_occlusion");
  spec.ao_samples = ao.integer("samples");
  lengths.ao_distance = ao.optional_number("distance");
  ao.finish();
  l.finish();
}

// A colour, or "transparent".
void read_background(TableReader& r, ShadingSpec& spec) {
  if (r.holds_string("background") && r.string("background") == "transparent") {
    spec.background_kind = BackgroundKind::transparent;
  } else {
    spec.background = r.color("background");
  }
  if (r.has("background_bottom")) {
    if (spec.background_kind == BackgroundKind::transparent)
      r.fail_at("background_bottom", "needs a background colour to fade from, not \"transparent\"");
    spec.background_kind = BackgroundKind::gradient;
    spec.background_bottom = r.color("background_bottom");
  } else {
    r.allow("background_bottom");
    spec.background_bottom = spec.background;
  }
}

void read_render(TableReader& r, SceneSpec& spec) {
  RenderSpec& render = spec.render;
  render.width = r.optional_integer("width");
  render.height = r.optional_integer("height");
  render.samples = r.integer("samples");
  render.shadow_offset = r.optional_number("shadow_offset");
  read_background(r, spec.shading);
  ContextSpec& context = spec.context;
  context.glyphs = r.boolean("glyphs");
  context.trajectories = r.boolean("trajectories");
  context.trajectory_radius = r.optional_number("trajectory_radius");
  spec.shading.trajectory_color = r.color("trajectory_color");
  if (!context.glyphs && !context.trajectories)
    r.fail_at("glyphs", "= false needs render.trajectories = true: otherwise nothing is drawn");
  context.ground = r.boolean("ground");
  context.ground_height = r.optional_number("ground_height");
  spec.shading.ground_shadow = r.number("ground_shadow");
  context.box = r.optional_boolean("box");
  spec.shading.box_color = r.color("box_color");
  context.box_radius = r.optional_number("box_radius");
  context.shell = r.optional_boolean("shell");
  spec.shading.shell_color = r.color("shell_color");
  spec.shading.shell_opacity = r.number("shell_opacity");
  spec.shading.shell_edge_opacity = r.number("shell_edge_opacity");
  if (r.has("intersector")) render.intersector = r.choice<Intersector>("intersector", {{"sphere", Intersector::sphere}, {"exact", Intersector::exact}});
  else r.allow("intersector");
  if (render.intersector == Intersector::exact && !shape_is_quadric(spec.surface.shape))
    r.fail_at("intersector", "= \"exact\" needs glyphs.shape = \"ellipsoid\": a superquadric's distance is not a "
                             "polynomial along a ray (use \"sphere\")");
  if (render.intersector == Intersector::exact && !exact_crossing_supported(spec.surface.kernel, spec.surface.blend))
    r.fail_at("intersector", "= \"exact\" needs surface.kernel \"wyvill\" or \"quartic\" (or surface.blend = \"max\"): "
                             "blinn's exponential is not a polynomial along a ray");
  render.min_step = r.optional_number("min_step");
  render.max_steps = r.integer("max_steps");
  r.finish();
}

void read_figure(TableReader& f, FigureSpec& spec) {
  spec.columns = f.optional_integer("columns");
  spec.labels = f.boolean("labels");
  spec.caption = f.string("caption");
  f.finish();
}

// Each [[panel]]: its label, and every other key (dotted, or in sub-tables)
// an override of the scene for that panel, checked when the panel is read.
void read_panels(TableReader& top, const toml::table& root, std::vector<PanelSpec>& panels) {
  top.allow("panel");
  const toml::node* node = root.get("panel");
  if (!node) return;
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables()) top.fail_at("panel", "must be tables: [[panel]], one per panel");
  if (array->size() > 26) top.fail_at("panel", "must be at most 26 panels, (a) to (z)");
  for (const toml::node& element : *array) {
    const toml::table& table = *element.as_table();
    PanelSpec panel;
    panel.line = int(table.source().begin.line);
    for_each_leaf(table, "", [&](const std::string& path, const toml::node& value) {
      if (path == "label") {
        if (!value.is_string()) top.fail_at("panel", "label must be a string");
        panel.label = value.as_string()->get();
      } else {
        if (!find_scene_key(path) && !is_scene_table(path))
          throw SceneError(source_location(value) + ": [[panel]] key " + path + " is not a scene key" +
                           nearest_key_hint(path));
        panel.overrides.push_back(path + "=" + toml_text(value));
      }
    });
    panels.push_back(std::move(panel));
  }
}

void read_output(TableReader& o, OutputSpec& spec, GlyphShape shape, const std::string& base_dir) {
  spec.file = o.optional_string("file");
  if (spec.file && !is_supported_image_path(*spec.file))
    o.fail_at("file", "must end in .png, .tif, .tiff, .exr, .pdf or .svg, got \"" + *spec.file + "\"");
  // A scene names its picture, the command line its folder (-o): a scene
  // never writes outside that folder, whoever wrote the scene.
  if (spec.file) {
    const std::filesystem::path name(*spec.file);
    const bool climbs = std::any_of(name.begin(), name.end(), [](const std::filesystem::path& part) { return part == ".."; });
    if (name.is_absolute() || climbs || name.has_root_name())
      o.fail_at("file", "must be a name inside the output folder (-o), not a path out of it, got \"" + *spec.file +
                            "\": give the folder with -o");
  }
  const bool exr = spec.file && is_scene_linear_format(*spec.file);
  spec.bit_depth = o.optional_integer("bit_depth");
  if (spec.bit_depth && (exr ? *spec.bit_depth != 16 && *spec.bit_depth != 32 : *spec.bit_depth != 8 && *spec.bit_depth != 16))
    o.fail_at("bit_depth", exr ? "must be 16 (half) or 32 (float) for an EXR" : "must be 8 or 16");
  spec.layers.clear();
  for (const std::string& name : o.strings("layers")) {
    for (Plane p : {Plane::depth, Plane::normal, Plane::scalar, Plane::id})
      if (name == plane_info(p).name) spec.layers.push_back(p);
  }
  spec.dpi = o.number("dpi");
  if (const std::vector<double> size = o.numbers("print_size"); !size.empty())
    spec.print_size = std::array<double, 2>{size[0], size[1]};
  if (const std::optional<std::string> config = o.optional_string("ocio_config"))
    spec.ocio_config = existing_file(o, "ocio_config", *config, base_dir);
  spec.display = o.optional_string("display");
  spec.view = o.optional_string("view");
  spec.colorbar = o.boolean("colorbar");
  spec.colorbar_position =
      o.choice<LegendPlacement>("colorbar_position", {{"right", LegendPlacement::right}, {"bottom", LegendPlacement::bottom}});
  spec.colorbar_length = o.number("colorbar_length");
  spec.font_size = o.number("font_size");
  spec.colorbar_title = o.optional_string("colorbar_title");
  spec.shape_key = o.optional_boolean("shape_key");
  if (spec.shape_key.value_or(false) && shape != GlyphShape::signed_superquadric)
    o.fail_at("shape_key", "= true needs glyphs.shape = \"signed\": only its forms carry a meaning to key");
  o.finish();
}

toml::table parse_scene(const std::string& text, const std::string& path) {
  try {
    return toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source();
    throw SceneError(path + ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column) +
                     ": " + std::string(e.description()));
  }
}

}  // namespace

toml::table scene_table(const SceneSpec& spec) {
  toml::table root = parse_scene(spec.text, spec.path);
  for (const std::string& o : spec.overrides) apply_override(root, o);
  return root;
}

SceneSpec load_scene_text(const std::string& text, const std::string& path, const std::string& base_dir,
                          const std::vector<std::string>& overrides) {
  SceneSpec spec;
  spec.path = path;
  spec.base_dir = base_dir;
  spec.text = text;
  spec.overrides = overrides;
  const toml::table root = scene_table(spec);
  TableReader top(root, "", path);
  // Every table is read, present or not, so every key takes the schema's default.
  TableReader data = top.table("data"), region = top.table("region"), seeds = top.table("seeds"),
              trajectories = top.table("trajectories"), glyphs = top.table("glyphs");
  read_glyphs(glyphs, spec.pipeline, spec.surface, base_dir);
  if (spec.pipeline.placement == SourcePlacement::curve || spec.pipeline.placement == SourcePlacement::list) {
    // The sources come from the scene: no data set to read.
    if (top.has("data")) top.fail_at("data", "is not read with glyphs.placement = \"curve\" or \"list\"");
    if (top.has("seeds")) top.fail_at("seeds", "has no use with glyphs.placement = \"curve\" or \"list\"");
    if (top.has("region")) top.fail_at("region", "has no use with glyphs.placement = \"curve\" or \"list\"");
    spec.pipeline.data.kind = DataKind::none;
  } else {
    read_data(data, spec.pipeline.data, base_dir);
    read_seeds(seeds, spec.pipeline.seeds);
    read_region(region, spec.pipeline, base_dir);
  }
  read_trajectories(trajectories, spec.pipeline.trajectory);
  if (spec.pipeline.data.kind == DataKind::point_load && spec.pipeline.color == ColorScalar::array)
    throw SceneError(path + ": glyphs.color_by = \"array:" + spec.pipeline.data.file.color_array +
                     "\" needs data.file: the point load has no arrays");
  TableReader surface = top.table("surface"), color = top.table("color"), camera = top.table("camera"),
              light = top.table("light"), render = top.table("render"), output = top.table("output"),
              figure = top.table("figure");
  read_surface(surface, spec.surface);
  read_color(color, spec.color);
  read_camera(camera, spec.camera);
  read_light(light, spec.shading, spec.light);
  read_render(render, spec);
  // A shell that is not drawn needs no surface extracted from the data.
  spec.pipeline.data.file.boundary = spec.context.shell.value_or(true);
  read_output(output, spec.output, spec.surface.shape, base_dir);
  top.allow("sweep");  // read by the batch (renderer/app/batch.h), not here
  read_figure(figure, spec.figure);
  read_panels(top, root, spec.panels);
  top.finish();
  return spec;
}

SceneSpec load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  if (const std::string why = unreadable_input(path); !why.empty()) throw SceneError(path + ": " + why);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw SceneError(path + ": cannot read the scene file");
  // A file named as no scene that TOML cannot parse is some other file: said
  // as what it is, not as a TOML syntax error on its first line.
  if (std::filesystem::path(path).extension() != ".toml") {
    try {
      (void)toml::parse(text.str(), path);
    } catch (const toml::parse_error& e) {
      throw SceneError(unknown_file_message(path, std::to_string(e.source().begin.line) + ":" +
                                                      std::to_string(e.source().begin.column) + ": " +
                                                      std::string(e.description())));
    }
  }
  return load_scene_text(text.str(), path, std::filesystem::path(path).parent_path().string(), overrides);
}

void check_data_lengths(const SceneSpec& spec, double diagonal) {
  const toml::table root = scene_table(spec);
  for (const KeySchema& key : scene_keys()) {
    if (!key.data_length()) continue;
    const toml::node* node = root.at_path(key.path).node();
    const std::optional<double> value = node ? node->value<double>() : std::nullopt;
    if (!value || std::isinf(*value)) continue;
    const double lo = kSmallestLengthPerDiagonal * diagonal, hi = kLargestLengthPerDiagonal * diagonal;
    if (*value >= lo && *value <= hi) continue;
    std::ostringstream what;
    what << source_location(*node) << ": " << key.path << " must be a length between " << lo << " and " << hi
         << " (" << kSmallestLengthPerDiagonal << " to " << kLargestLengthPerDiagonal
         << " times the data's diagonal D = " << diagonal << "), got " << *value;
    throw SceneError(what.str());
  }
}

bool is_data_file(const std::string& path) { return is_known_data_file(path); }

SceneSpec load_scene_or_data_file(const std::string& path, const std::vector<std::string>& overrides) {
  return is_data_file(path) ? scene_for_data_file(path, overrides) : load_scene(path, overrides);
}

SceneSpec scene_for_data_file(const std::string& path, const std::vector<std::string>& overrides) {
  // The file is the user's own argument: said as such, not as a line of
  // the scene made for it.
  if (const std::string why = unreadable_input(path); !why.empty()) throw SceneError(path + ": " + why);
  if (const std::string why = unreadable_format_message(path); !why.empty()) throw SceneError(why);
  // The path as given, relative to where hsb runs: printed back by
  // `hsb info`, the scene works from there.
  std::ostringstream text;
  text << "[data]\nfile = " << toml::value<std::string>(path) << "\n";
  return load_scene_text(text.str(), path, "", overrides);
}

}  // namespace hsb
