#include "renderer/scene/scene_keys.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>

#include "field/glyphs/glyph_mapping.h"
#include "field/reading/component_order.h"
#include "field/reading/data_formats.h"
#include "renderer/image/colormap.h"
#include "renderer/render/camera_framing.h"
#include "renderer/render/render_image.h"
#include "renderer/surface/kernel.h"

namespace hsb {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A coordinate beyond this cannot be traced: rays are single precision.
constexpr double kLargestCoordinate = 1e17;

// One row of the schema, built up by its setters.
class Key {
 public:
  Key(std::string path, KeyType type, std::string doc) {
    k_.path = std::move(path);
    k_.type = type;
    k_.doc = std::move(doc);
  }
  Key& range(double lo, double hi, bool lo_open = false) {
    k_.range = {lo, hi, lo_open, false};
    return *this;
  }
  Key& positive(double hi = kInf) { return range(0.0, hi, true); }
  Key& non_negative(double hi = kInf) { return range(0.0, hi); }
  Key& infinite_allowed() {
    k_.range.allow_infinite = true;
    return *this;
  }
  Key& count(std::size_t n) {
    k_.count = n;
    return *this;
  }
  Key& choices(std::vector<std::string> names) {
    k_.choices = std::move(names);
    return *this;
  }
  Key& unit(std::string u) {
    k_.unit = std::move(u);
    return *this;
  }
  // A data length: > 0, and checked against the data's diagonal once read.
  Key& length() { return positive().unit("data length"); }
  Key& fallback(std::string toml) {
    k_.default_kind = KeyDefault::value;
    k_.fallback = std::move(toml);
    return *this;
  }
  Key& automatic(std::string rule) { return by(KeyDefault::automatic, std::move(rule)); }
  Key& derived(std::string rule) { return by(KeyDefault::derived, std::move(rule)); }
  Key& none(std::string rule = "none") { return by(KeyDefault::none, std::move(rule)); }
  operator KeySchema() const { return k_; }

 private:
  Key& by(KeyDefault kind, std::string rule) {
    k_.default_kind = kind;
    k_.rule = std::move(rule);
    return *this;
  }
  KeySchema k_;
};

using T = KeyType;

std::vector<std::string> kernel_names() {
  std::vector<std::string> names;
  for (const KernelTraits& k : all_kernel_traits()) names.emplace_back(k.name);
  return names;
}

std::vector<std::string> component_order_names() {
  std::vector<std::string> names;
  for (const ComponentOrder& o : component_orders()) names.push_back(o.name);
  return names;
}

std::vector<std::string> view_choices() {
  std::vector<std::string> names;
  for (const char* const* n = view_names(); *n; ++n) names.emplace_back(*n);
  return names;
}

std::vector<std::string> color_by_choices() {
  std::vector<std::string> names;
  for (ColorScalar c : named_color_scalars()) names.emplace_back(color_scalar_name(c));
  return names;
}

// The colour scalars of a tensor that a region can keep to.
std::vector<std::string> measure_choices() {
  std::vector<std::string> names;
  for (ColorScalar c : named_color_scalars())
    if (is_tensor_measure(c)) names.emplace_back(color_scalar_name(c));
  return names;
}

std::vector<std::string> layer_choices() {
  std::vector<std::string> names;
  for (Plane p : {Plane::depth, Plane::normal, Plane::scalar, Plane::id}) names.emplace_back(plane_info(p).name);
  return names;
}

std::vector<KeySchema> build_keys() {
  const double c = kLargestCoordinate;
  return {
      // [figure] and [[panel]]
      Key("figure.columns", T::integer, "panels per row").range(1, 16).derived("the count whose panels are nearest square"),
      Key("figure.labels", T::boolean, "(a), (b), … at each panel's top left").fallback("true"),
      Key("figure.caption", T::string, "text under the panels").none("no caption"),
      Key("panel.label", T::string, "text after the panel's letter").none(),

      // [data]
      Key("data.kind", T::choice, "the data set: Boussinesq's point load, or a VTK data file")
          .choices({"point_load", "vtk"})
          .derived("\"vtk\" when data.file is given, else \"point_load\""),
      Key("data.sign", T::choice, "which stress is positive: tension (mechanics) or compression (geomechanics, soil and rock)")
          .choices({"tension-positive", "compression-positive"}).fallback("\"tension-positive\""),
      Key("data.sample_grid", T::numbers, "resample onto a uniform grid of this many nodes per axis")
          .count(3).range(0, 1000).fallback("[0, 0, 0]"),
      Key("data.bounds", T::numbers, "the point load's domain [xmin, xmax, ymin, ymax, zmin, zmax]")
          .count(6).range(-c, c).fallback("[-1, 1, -1, 1, -1, 1]"),
      Key("data.load", T::number, "the point load P, pushing towards -z").fallback("1.0"),
      Key("data.poisson_ratio", T::number, "Poisson's ratio ν of the half-space").range(-1.0, 0.5).fallback("0.3"),
      Key("data.singular_radius", T::number, "within this distance of the load the field is held constant")
          .length().automatic("D/1000"),
      Key("data.file", T::string, "the data file (" + readable_extensions_text() + "), relative to the scene").none("required for \"vtk\""),
      Key("data.array", T::string, "the field's array")
          .derived("the active tensors, else one whose name says stress, then strain, else the first; vectors only without tensors"),
      Key("data.step", T::integer, "the step of a time series (.pvd, or Exodus with time steps) to read, from 0").range(0, std::numeric_limits<int>::max())
          .derived("every step, one image each"),
      Key("data.block", T::string, "one block of a file of blocks (.vtm, Exodus), by name or index from 0")
          .derived("all blocks, merged"),
      Key("data.components", T::choice, "the order of a 6-component array's tensor components")
          .choices(component_order_names())
          .derived("the order the file records (components named apart, NRRD's and NIfTI's layouts), else \"vtk\""),
      Key("data.frame", T::choice, "the axes a volume's tensors are written in")
          .choices({"world", "voxel", "fsl"})
          .derived("the format's: NRRD's measurement frame, FSL's voxel axes for FSL's and NIfTI's symmetric-matrix "
                   "layouts (dtifit's, DIPY's), the scanner's for MRtrix; else the data's space (\"world\")"),
      Key("data.quantity", T::choice, "what the tensors are: stress (or strain) or diffusion")
          .choices({"stress", "diffusion"})
          .automatic("\"diffusion\" where the tensors are positive definite and not flat (90 % with λ3 > 0, 20 % in a "
                     "scan placed in anatomical space; median "
                     "λ3/λ1 ≥ 0.05) with water's mean diffusivity (1e-4 to 1e-2 mm²/s, 1e-10 to 1e-8 m²/s, 0.1 to 10 "
                     "µm²/ms); else \"stress\""),
      Key("data.field", T::choice, "read only tensors or only vectors").choices({"auto", "tensor", "vector"}).fallback("\"auto\""),
      Key("data.association", T::choice, "point or cell data").choices({"auto", "point", "cell"}).fallback("\"auto\""),
      Key("data.cell_tensors", T::choice, "cell data constant per cell, or averaged onto the points")
          .choices({"constant", "averaged"}).fallback("\"constant\""),

      // [region]
      Key("region.measure", T::choice, "the measure of the tensor the region keeps to").choices(measure_choices())
          .fallback("\"fa\""),
      Key("region.above", T::number, "seeds, lines and glyphs at data points only where the measure is at least this")
          .automatic("0.3 for diffusion data (with fa: the white matter); else none, everywhere"),
      Key("region.mask", T::string, "seeds, lines and glyphs at data points only where this mask is at least ½: "
                                    "\"array:NAME\" (a scalar array of the data file) or a file of one value per "
                                    "voxel, point or cell (a brain mask), relative to the scene")
          .none("everywhere (with region.above as well, where given)"),

      // [seeds]
      Key("seeds.strategy", T::choice, "how seeds are chosen: evenly spaced trajectories, a grid, or the points given")
          .choices({"even", "grid", "points"}).automatic("\"even\", or \"points\" when points or grids are given"),
      Key("seeds.separation", T::number, "even: the distance between neighbouring trajectories")
          .length().automatic("(body volume/150)^(1/3); (area/200)^(1/2) in 2-D"),
      Key("seeds.importance", T::boolean, "even: trajectories closer where the magnitude is larger")
          .automatic("on for stress, off for diffusion and a flow"),
      Key("seeds.frame", T::choice, "seed coordinates in the data's own units, or as fractions of its bounds")
          .choices({"world", "bounds"}).fallback("\"world\""),
      Key("seeds.points", T::points, "explicit seeds [[x, y, z], ...]; with \"even\", taken first")
          .automatic("none; \"even\" records the seeds it took"),
      Key("seeds.grid", T::tables, "grids of seeds on parallelograms, [[seeds.grid]]")
          .automatic("with \"grid\": a 5×5 grid across the middle of the data's longest axis"),
      Key("seeds.grid.corner", T::vector, "one corner of the parallelogram").fallback("[0, 0, 0]"),
      Key("seeds.grid.edge_u", T::vector, "its first edge").fallback("[1, 0, 0]"),
      Key("seeds.grid.edge_v", T::vector, "its second edge").fallback("[0, 1, 0]"),
      Key("seeds.grid.n", T::integer, "seeds along edge_u").range(1, 10000).fallback("3"),
      Key("seeds.grid.m", T::integer, "seeds along edge_v").range(1, 10000).fallback("3"),

      // [trajectories]
      Key("trajectories.family", T::choice, "the eigenvector followed (\"major+minor\": both, each with its own lines)")
          .choices({"major", "medium", "minor", "major+minor"})
          .automatic("tensors seeded evenly: \"major+minor\" where tension and compression are both present, else "
                     "the family of the one sign (\"major\" for tension, \"minor\" for compression); else \"major\""),
      Key("trajectories.step", T::number, "RK4 step, in arc length").length().automatic("D/400"),
      Key("trajectories.max_length", T::number, "longest trajectory in each direction").length().automatic("2·D"),
      Key("trajectories.degeneracy", T::number, "stop where the eigenvalue gap is below this fraction of max|λ|")
          .range(0.0, 1.0).fallback("0.001"),
      Key("trajectories.min_magnitude", T::number, "stop where the tensor's norm (the flow's speed) falls below this")
          .non_negative().unit("data magnitude").automatic("0 for tensors; a thousandth of the largest speed for a flow"),
      Key("trajectories.max_steps", T::integer, "guard on the steps per direction").range(1, std::numeric_limits<int>::max()).fallback("100000"),
      Key("trajectories.direction", T::choice, "trace both ways, or only along or against the field")
          .choices({"both", "forward", "backward"}).fallback("\"both\""),
      Key("trajectories.stop_below", T::number, "end lines where region.measure falls below this")
          .automatic("region.above: lines end at the region's edge; none without a region"),
      Key("trajectories.max_turn", T::number, "stop before a step that turns more than this many degrees from the last")
          .range(0.0, 180.0).automatic("180: no limit"),
      Key("trajectories.method", T::choice, "follow the eigenvector, or Weinstein's tensorlines: the major eigenvector where the tensor is linear, straight on (bent by the tensor) where it is planar or isotropic, so lines cross fibre crossings")
          .choices({"eigenvector", "tensorlines"}).fallback("\"eigenvector\""),
      Key("trajectories.puncture", T::number, "tensorlines: how much the tensor bends a line where it is not linear (0: straight on, 1: by the tensor alone)")
          .range(0.0, 1.0).fallback("0.5"),

      // [glyphs]
      Key("glyphs.placement", T::choice, "where sources go: along trajectories, at seeds, at the data's points, along a curve, from a list")
          .choices({"trajectories", "seeds", "points", "curve", "list"}).fallback("\"trajectories\""),
      Key("glyphs.spacing", T::number, "arc length between sources along a trajectory").length()
          .automatic("D/40; D/25 for normalized and constant"),
      Key("glyphs.beads", T::number, "glyphs end to end along each trajectory, overlapping by this fraction of their lengths (0: tip to tip; below 0, a gap), instead of every spacing")
          .range(-0.9, 0.9).automatic("0 for shape = \"signed\" when spacing is not given; else off, sources every spacing"),
      Key("glyphs.stride", T::integer, "placement = \"points\": a glyph at every stride-th data point").range(1, std::numeric_limits<int>::max())
          .automatic("at most 20,000 glyphs"),
      Key("glyphs.mapping", T::choice, "radii from eigenvalues").choices({"linear", "sqrt", "normalized", "constant"}).fallback("\"sqrt\""),
      Key("glyphs.scale", T::number, "s of the mapping").positive().automatic("the 90th-percentile glyph is D/50 across"),
      Key("glyphs.floor", T::number, "smallest radius").length().automatic("a twentieth of the reference glyph's"),
      Key("glyphs.ceiling", T::number, "largest radius (inf for none)").length().infinite_allowed()
          .automatic("three times the reference glyph's"),
      Key("glyphs.color_by", T::choice, "the colour scalar, or \"array:NAME\"").choices(color_by_choices())
          .automatic("the traced family's eigenvalue (major: \"lambda1\"; several families: \"family_eigenvalue\", "
                     "each line's own) for stress, \"direction\" for diffusion, \"speed\" for a flow"),
      Key("glyphs.thickness", T::number, "2-D data: the glyphs' thickness across the plane").length()
          .automatic("each glyph's smaller in-plane diameter"),
      Key("glyphs.shape", T::choice, "each glyph's form").choices({"ellipsoid", "superquadric", "signed"})
          .automatic("\"superquadric\" for a diffusion volume's glyphs at its points (as Teem draws them); else \"ellipsoid\""),
      Key("glyphs.sharpness", T::number, "superquadric and signed: γ, how sharp its edges (Teem's tend glyph -sh)")
          .range(0.0, 10.0).fallback("3"),
      Key("glyphs.stretch", T::number, "streamballs: the radius along the flow times this").range(1.0, 100.0).fallback("1"),
      Key("glyphs.file", T::string, "placement = \"list\": the CSV file of sources").none(),
      Key("glyphs.curve.kind", T::choice, "the curve").choices({"line", "circle", "helix", "polyline"}).fallback("\"helix\""),
      Key("glyphs.curve.from", T::vector, "a line's start").fallback("[0, 0, 0]"),
      Key("glyphs.curve.to", T::vector, "a line's end").fallback("[1, 0, 0]"),
      Key("glyphs.curve.centre", T::vector, "a circle's centre, a helix's first turn's").fallback("[0, 0, 0]"),
      Key("glyphs.curve.radius", T::number, "a circle's or helix's radius").positive(c).fallback("1"),
      Key("glyphs.curve.axis", T::direction, "a circle's normal, a helix's axis").fallback("[0, 0, 1]"),
      Key("glyphs.curve.pitch", T::number, "a helix's rise per turn").non_negative(c).fallback("1"),
      // A helix is drawn as 256 segments a turn; more than 10,000 turns are
      // more than glyphs.curve.count (at most 100,000) could show anyway.
      Key("glyphs.curve.turns", T::number, "a helix's turns").positive(10000.0).fallback("2"),
      Key("glyphs.curve.points", T::points, "a polyline's points, at least two").none(),
      Key("glyphs.curve.count", T::integer, "number of sources").range(1, 100000).fallback("12"),
      Key("glyphs.curve.semi_axes", T::numbers, "each glyph's semi-axes alone").count(3).positive(c).fallback("[0.3, 0.1, 0.1]"),

      // [surface]
      Key("surface.kernel", T::choice, "the metaball kernel K(u)").choices(kernel_names()).fallback("\"wyvill\""),
      Key("surface.blend", T::choice, "F = Σ K (metaballs) or max K (a union)").choices({"sum", "max"}).fallback("\"sum\""),
      Key("surface.influence_radius", T::number, "R, the same for every source").positive().fallback("1.0"),
      Key("surface.isovalue", T::number, "C, the surface's level").range(0.0, 1.0, true).fallback("0.5"),

      // [color]
      Key("color.map", T::choice, "the colormap").choices(colormap_names())
          .automatic("\"coolwarm\" when the values have both signs (and for the mode), else \"viridis\""),
      Key("color.range", T::numbers, "[low, high] of the colour scalar").count(2)
          .automatic("the values' extremes, outliers beyond a fence past the 2nd/98th percentile clipped; [0, 1] for fa, cl, cp and cs, [-1, 1] for the mode"),
      Key("color.symmetric", T::boolean, "an automatic range symmetric about zero").derived("true for a diverging map"),
      Key("color.scale", T::choice, "colour by the scalar or its logarithm").choices({"linear", "log"}).fallback("\"linear\""),

      // [camera]
      Key("camera.view", T::view, "a named view or a direction [x, y, z] towards the camera").choices(view_choices())
          .automatic("front-right and above; from the side for a long body"),
      Key("camera.projection", T::choice, "perspective or parallel rays").choices({"perspective", "orthographic"})
          .fallback("\"perspective\""),
      Key("camera.frame", T::choice, "what to fit in the picture").choices({"drawn", "glyphs", "data"}).fallback("\"drawn\""),
      Key("camera.margin", T::number, "free space on each side, a fraction of the picture").range(0.0, 0.45).fallback("0.05"),
      Key("camera.position", T::vector, "the eye point").automatic("framing what is drawn"),
      Key("camera.look_at", T::vector, "the point at the centre of the view").automatic("framing what is drawn"),
      Key("camera.up", T::direction, "the picture's up").automatic("[0, 0, 1], or [0, 1, 0] looking along z"),
      // Down to a ten-thousandth of a degree: narrower, the automatic camera
      // would stand beyond the ray tracer's range.
      Key("camera.fov", T::number, "vertical field of view (perspective)").range(1e-4, 179.0).unit("degrees").fallback("30"),
      Key("camera.height", T::number, "the view's height (orthographic)").length().automatic("framing what is drawn"),

      // [light]. Light levels are fractions of white; a hundred times it
      // already washes every glyph out to one flat colour.
      Key("light.from", T::direction, "direction towards the key light").fallback("[1, -1.5, 2.5]"),
      Key("light.color", T::color, "the key light's colour, display sRGB").fallback("[1, 1, 1]"),
      Key("light.intensity", T::number, "the key light's level").range(0.0, 100.0).unit("fraction of white").fallback("0.85"),
      Key("light.size", T::number, "the key light's angular diameter (0: hard shadows)").range(0.0, 90.0).unit("degrees").fallback("5"),
      Key("light.samples", T::integer, "shadow rays per camera sample").range(1, 64).fallback("4"),
      Key("light.shadows", T::boolean, "the key light casts shadows").fallback("true"),
      Key("light.fill", T::number, "the fill light's level").range(0.0, 100.0).unit("fraction of white").fallback("0.25"),
      Key("light.fill_from", T::direction, "direction towards the fill light").fallback("[-1.5, -1, 0.5]"),
      Key("light.ambient", T::number, "ambient light, shadowed by occlusion").range(0.0, 100.0).unit("fraction of white").fallback("0.4"),
      Key("light.specular", T::number, "Blinn–Phong highlight level").range(0.0, 100.0).unit("fraction of white").fallback("0.25"),
      Key("light.shininess", T::number, "Blinn–Phong exponent").positive().fallback("40"),
      Key("light.ambient_occlusion.samples", T::integer, "occlusion rays per camera sample (0: off)").range(0, 256).fallback("2"),
      Key("light.ambient_occlusion.distance", T::number, "how far an occluder still darkens").length()
          .automatic("four median glyphs"),

      // [render]
      Key("render.width", T::integer, "picture width").range(1, 16384).unit("pixels")
          .automatic("output.print_size at output.dpi, else the body's shape from render.height, or at 800² pixels"),
      Key("render.height", T::integer, "picture height").range(1, 16384).unit("pixels")
          .automatic("output.print_size at output.dpi, else the body's shape from render.width, or at 800² pixels"),
      Key("render.samples", T::integer, "samples×samples per pixel").range(1, 16).fallback("2"),
      Key("render.background", T::color, "display sRGB, or \"transparent\"").choices({"transparent"}).fallback("[1, 1, 1]"),
      Key("render.background_bottom", T::color, "a vertical gradient's bottom colour").none("no gradient"),
      Key("render.glyphs", T::boolean, "draw the glyphs").fallback("true"),
      Key("render.trajectories", T::boolean, "draw the trajectories as thin tubes").fallback("false"),
      Key("render.trajectory_radius", T::number, "the tubes' radius").length().automatic("a fifth of the median glyph"),
      Key("render.trajectory_color", T::color, "the tubes' colour").fallback("[0.25, 0.25, 0.25]"),
      Key("render.ground", T::boolean, "a plane that catches the key light's shadow").fallback("false"),
      Key("render.ground_height", T::number, "z of the ground").range(-c, c).unit("data coordinate")
          .automatic("just below the lowest thing framed"),
      Key("render.ground_shadow", T::number, "how dark the shadow on the ground is").range(0.0, 1.0).fallback("0.5"),
      Key("render.box", T::boolean, "draw the domain's edges").automatic("true for point_load, false for vtk"),
      Key("render.box_color", T::color, "the edges' colour").fallback("[0.05, 0.05, 0.05]"),
      Key("render.box_radius", T::number, "the edges' thickness").length().automatic("D/500"),
      Key("render.shell", T::boolean, "draw the data's boundary as a translucent shell").automatic("false for point_load, true for vtk"),
      Key("render.shell_color", T::color, "the shell's colour").fallback("[0.6, 0.65, 0.7]"),
      Key("render.shell_opacity", T::number, "the shell's opacity facing the viewer").range(0.0, 1.0).fallback("0.08"),
      Key("render.shell_edge_opacity", T::number, "the shell's opacity at grazing angles").range(0.0, 1.0).fallback("0.6"),
      Key("render.shadow_offset", T::number, "shadow rays start this far off the surface").length()
          .automatic("a tenth of a pixel at the depth framed"),
      Key("render.intersector", T::choice, "exact polynomial roots or sphere tracing").choices({"sphere", "exact"})
          .automatic("\"exact\" where it applies, else \"sphere\""),
      Key("render.min_step", T::number, "the sphere tracer's smallest step").length().automatic("D·1e-6"),
      Key("render.max_steps", T::integer, "sphere-tracing steps per ray").range(1, std::numeric_limits<int>::max()).fallback("200000"),

      // [output]
      Key("output.file", T::string, "the image, relative to -o; its extension picks the format")
          .automatic("<scene name>.png"),
      Key("output.bit_depth", T::integer, "8 or 16 for PNG and TIFF; 16 or 32 for EXR").range(8, 32)
          .automatic("8 for PNG and TIFF, 32 for EXR"),
      Key("output.layers", T::strings, "an EXR's channels besides RGBA").choices(layer_choices())
          .fallback("[\"depth\", \"normal\", \"scalar\", \"id\"]"),
      Key("output.dpi", T::number, "written into the image; the legend's points are at it").range(1.0, 10000.0).fallback("300"),
      Key("output.print_size", T::numbers, "[width, height]: the picture's size at dpi").count(2).positive().unit("mm").none(),
      Key("output.ocio_config", T::string, "an OpenColorIO config file").none("$OCIO, else the built-in config"),
      Key("output.display", T::string, "the OCIO display").derived("the config's default"),
      Key("output.view", T::string, "the OCIO view").derived("the config's default"),
      Key("output.colorbar", T::boolean, "draw the legend: the colour bar, and the shape key where there is one").fallback("true"),
      Key("output.colorbar_title", T::string, "the colour bar's title").automatic("named after glyphs.color_by"),
      Key("output.colorbar_position", T::choice, "where the colour bar goes").choices({"right", "bottom"}).fallback("\"right\""),
      Key("output.colorbar_length", T::number, "of the picture's height (right) or width (bottom)").range(0.1, 1.0).fallback("0.6"),
      Key("output.shape_key", T::boolean, "sample glyphs labelled tension, compression and shear beside the colour bar")
          .automatic("true for glyphs.shape = \"signed\"; needs it"),
      Key("output.font_size", T::number, "the legend's text").range(1.0, 72.0).unit("points").fallback("7"),
  };
}

// The keys by path, and each default parsed once.
struct SchemaIndex {
  std::map<std::string, const KeySchema*, std::less<>> by_path;
  std::map<std::string, toml::table, std::less<>> defaults;
};

const SchemaIndex& index() {
  static const SchemaIndex built = [] {
    SchemaIndex i;
    for (const KeySchema& k : scene_keys()) {
      i.by_path.emplace(k.path, &k);
      if (k.default_kind == KeyDefault::value) i.defaults.emplace(k.path, toml::parse("v = " + k.fallback));
    }
    return i;
  }();
  return built;
}

std::string number_text(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// Edits needed to turn a into b (the usual Levenshtein distance).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

const std::vector<KeySchema>& scene_keys() {
  static const std::vector<KeySchema> keys = build_keys();
  return keys;
}

const KeySchema* find_scene_key(std::string_view path) {
  const auto& by_path = index().by_path;
  const auto it = by_path.find(path);
  return it == by_path.end() ? nullptr : it->second;
}

const KeySchema& scene_key(std::string_view path) {
  if (const KeySchema* key = find_scene_key(path)) return *key;
  throw std::logic_error("the scene schema has no key " + std::string(path));
}

bool is_scene_table(std::string_view path) {
  const std::string prefix = std::string(path) + ".";
  return std::any_of(scene_keys().begin(), scene_keys().end(),
                     [&](const KeySchema& k) { return k.path.rfind(prefix, 0) == 0; });
}

std::string nearest_key_hint(std::string_view path) {
  const KeySchema* best = nullptr;
  std::size_t best_distance = 4;  // further than three edits is a different word
  for (const KeySchema& k : scene_keys()) {
    // Lengths further apart than that need more edits: not worth the
    // quadratic distance (a fuzzer's key of 100 kB took seconds).
    const std::size_t apart = path.size() > k.path.size() ? path.size() - k.path.size() : k.path.size() - path.size();
    if (apart >= best_distance) continue;
    const std::size_t d = edit_distance(path, k.path);
    if (d < best_distance) best = &k, best_distance = d;
  }
  return best ? "; did you mean " + best->path + "?" : "";
}

const toml::node* default_node(const KeySchema& key) {
  const auto& defaults = index().defaults;
  const auto it = defaults.find(key.path);
  return it == defaults.end() ? nullptr : it->second.get("v");
}

std::string range_text(const KeySchema& key) {
  const NumberRange& r = key.range;
  const bool no_low = r.lo == -kInf, no_high = r.hi == kInf;
  std::string text;
  if (no_low && no_high) text = "any number";
  else if (no_high) text = (r.lo_open ? "> " : ">= ") + number_text(r.lo);
  else text = std::string("in ") + (r.lo_open ? "(" : "[") + number_text(r.lo) + ", " + number_text(r.hi) + "]";
  if (r.allow_infinite) text += ", or inf";
  return text;
}

std::string type_text(const KeySchema& key) {
  switch (key.type) {
    case T::number: return "number";
    case T::integer: return "integer";
    case T::boolean: return "true or false";
    case T::string: return "string";
    case T::choice: return "name";
    case T::view: return "name or [x, y, z]";
    case T::vector: return "[x, y, z]";
    case T::direction: return "[x, y, z], not zero";
    case T::color: return "[r, g, b] or \"#rrggbb\"";
    case T::numbers: return key.count ? std::to_string(key.count) + " numbers" : "numbers";
    case T::points: return "[[x, y, z], ...]";
    case T::strings: return "[strings]";
    case T::tables: return "[[tables]]";
  }
  return "";
}

std::string values_text(const KeySchema& key) {
  std::string text;
  const auto quoted = [&] {
    std::string names;
    for (const std::string& c : key.choices) names += (names.empty() ? "\"" : ", \"") + c + "\"";
    return names;
  };
  switch (key.type) {
    case T::number:
    case T::integer:
    case T::numbers: text = range_text(key); break;
    case T::choice:
    case T::view:
    case T::strings: text = quoted(); break;
    case T::color: text = key.choices.empty() ? "components in [0, 1]" : "components in [0, 1], or " + quoted(); break;
    case T::vector:
    case T::direction:
    case T::points: text = "coordinates within ±1e17"; break;
    default: break;
  }
  if (key.data_length())
    text += (text.empty() ? "" : "; ") + std::string("between D·") + number_text(kSmallestLengthPerDiagonal) +
            " and D·" + number_text(kLargestLengthPerDiagonal);
  return text;
}

}  // namespace hsb
