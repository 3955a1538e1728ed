#include "renderer/library/prepared_scene.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <filesystem>

#include "base/huge_pages.h"
#include "base/memory_budget.h"
#include "base/point_extremes.h"
#include "base/process_memory.h"
#include "base/thread_room.h"
#include "field/reading/data_formats.h"
#include "renderer/image/image_io_module.h"
#include "renderer/image/image_output.h"
#include <sstream>

namespace hsb {
namespace {

// The automatic lengths of the renderer, as fractions of the data's size D
// or of a median glyph's size.
constexpr double kBoxRadiusPerDiagonal = 1.0 / 500.0;
// Shadow and occlusion rays start this many pixels off the surface (at the
// depth of what is framed): far below anything a picture shows, and far
// enough out that a ray leaving a dense crowd of sources, where the field
// starts just under C, is soon proven clear of it.
constexpr double kShadowOffsetPerPixel = 0.1;
constexpr double kMinStepPerDiagonal = 1e-6;
constexpr double kTubePerGlyph = 0.2;
constexpr double kOcclusionPerGlyph = 4.0;
constexpr int kDefaultPixels = 800;
constexpr double kTallest = 0.5, kWidest = 2.5;  // the automatic picture's aspect
// Influence regions a ray crosses on average beyond which a render is slow
// (the figure scenes stay under 10; fig05 without its ceiling is over 2000).
constexpr double kCrowdedRay = 100.0;
// Memory a pixel takes at most: the film with every plane, the display
// image and the encoder's copy; where the picture is written as it is
// made, its bytes, all waiting for the image module at worst, and the
// encoded file, no larger.
constexpr double kBytesPerPixel = 64.0;
constexpr double kStreamedBytesPerPixel = 8.0;
// Memory a source takes once the scene is prepared: the span BVH and the
// render's own lists (290–300 bytes a source measured on fig09 with
// 110,000 and 157,000 sources, from this estimate to the peak).
constexpr double kRenderBytesPerSource = 300.0;
// How far beyond an isolated glyph's level surface the camera allows for
// blending: two coincident wyvill sources at C = ½ reach 1.38 times as
// far, three 1.56 times; a tube of overlapping glyphs lies between.
constexpr double kBlendAllowance = 1.6;

// The median of the glyphs' sizes (largest semi-axes alone); D/50 when
// there are none.
double median_glyph_size(const std::vector<GlyphSource>& sources, double extent, double diagonal) {
  if (sources.empty()) return diagonal / 50.0;
  std::vector<double> sizes;
  sizes.reserve(sources.size());
  for (const GlyphSource& g : sources) sizes.push_back(extent * g.radii.maxCoeff());
  std::nth_element(sizes.begin(), sizes.begin() + std::ptrdiff_t(sizes.size() / 2), sizes.end());
  return sizes[sizes.size() / 2];
}

// "major", or "major+minor" for several families, as the scene names them.
std::string family_names(const std::vector<EigenFamily>& families) {
  static const char* const names[] = {"major", "medium", "minor"};
  std::string text;
  for (EigenFamily f : families) text += (text.empty() ? "" : "+") + std::string(names[int(f)]);
  return text;
}

// The colour bar's automatic title.
std::string scalar_title(ColorScalar scalar, const SceneSpec& spec) {
  switch (scalar) {
    case ColorScalar::family_eigenvalue: return "each line's eigenvalue: λ₁ on major, λ₃ on minor";
    case ColorScalar::lambda1: return "major eigenvalue λ₁";
    case ColorScalar::lambda2: return "medium eigenvalue λ₂";
    case ColorScalar::lambda3: return "minor eigenvalue λ₃";
    case ColorScalar::mean: return "mean eigenvalue (λ₁ + λ₂ + λ₃)/3";
    case ColorScalar::von_mises: return "von Mises stress";
    case ColorScalar::fa: return "fractional anisotropy FA";
    case ColorScalar::trace: return "trace λ₁ + λ₂ + λ₃";
    case ColorScalar::westin_linear: return "linear anisotropy cₗ";
    case ColorScalar::westin_planar: return "planar anisotropy cₚ";
    case ColorScalar::westin_spherical: return "isotropy cₛ";
    case ColorScalar::mode: return "mode: −1 planar, +1 linear";
    case ColorScalar::direction: return "direction of e₁ (grey where FA is low)";
    case ColorScalar::speed: return "speed |v|";
    case ColorScalar::array:
      return spec.pipeline.placement == SourcePlacement::list ? "scalar" : spec.pipeline.data.file.color_array;
    case ColorScalar::arc_length: return "position along the curve";
    case ColorScalar::none: return "";
  }
  return "";
}

// Whether a colour scalar is a normal stress, whose sign says tension or
// compression.
bool carries_stress_sign(ColorScalar scalar) {
  return scalar == ColorScalar::lambda1 || scalar == ColorScalar::lambda2 || scalar == ColorScalar::lambda3 ||
         scalar == ColorScalar::mean || scalar == ColorScalar::family_eigenvalue;
}

// The colormap (automatic: diverging for signed values, sequential
// otherwise) and the range, with the values' true extremes for the bar.
// An automatic diverging map of stress runs from compression (cool) to
// tension (warm) whichever sign the data calls positive, so that a
// geomechanics figure and a mechanics one of the same state look alike:
// with compression positive it is reversed.
ColorScale color_scale(const SceneSpec& scene, const GlyphScene& glyphs) {
  const ColorSpec& spec = scene.color;
  const ColorScalar scalar = glyphs.color;
  const std::optional<std::array<double, 2>>& data_extremes = glyphs.color_extremes;
  std::vector<double> values;
  values.reserve(glyphs.sources.size());
  for (const GlyphSource& s : glyphs.sources) values.push_back(s.scalar);
  // A bounded measure spans its whole range, and picks its colormap by it.
  const std::optional<std::array<double, 2>> natural = spec.log ? std::nullopt : natural_range(scalar);
  const Colormap* automatic =
      &colormap_for(spec.map, natural ? std::vector<double>(natural->begin(), natural->end()) : values, spec.log);
  if (!spec.map && automatic->diverging && scene.pipeline.data.sign == SignConvention::compression_positive &&
      carries_stress_sign(scalar))
    automatic = &colormap_named(automatic->name + "_r");
  const Colormap& map = *automatic;
  ColorScale scale{&map, 0.0, 1.0, spec.log};
  if (!spec.range && !natural) {
    scale = auto_scale(map, color_range_values(glyphs), spec.symmetric.value_or(map.diverging), spec.log);
  } else {
    const std::array<double, 2> range = spec.range ? *spec.range : *natural;
    scale.lo = range[0], scale.hi = range[1];
    record_extremes(scale, values);
  }
  // The data's own extremes where the glyphs do not reach them: the bar
  // marks them (a log scale's only where positive).
  if (data_extremes) {
    const auto [lo, hi] = *data_extremes;
    if (!spec.log || lo > 0.0) scale.data_lo = std::isnan(scale.data_lo) ? lo : std::min(scale.data_lo, lo);
    if (!spec.log || hi > 0.0) scale.data_hi = std::isnan(scale.data_hi) ? hi : std::max(scale.data_hi, hi);
  }
  return scale;
}

void add_corners(const Box3& b, std::vector<Vec3>& points) {
  const std::array<Vec3, 8> c = b.corners();
  points.insert(points.end(), c.begin(), c.end());
}

// Points on each glyph the camera frames: the tips of its axes and the
// eight points midway between them, on the glyph's own shape (the
// ellipsoid's at 1/√3 of each axis, a sharp superquadric's out at its
// corners, up to the whole axes), scaled to the isolated glyph's level
// surface times kBlendAllowance (neighbours blending swell a tube; never
// beyond the support). The glyph's shape, not its box: a box's corners
// frame a thin, tilted glyph train far too loosely.
void add_glyph_points(const PreparedScene& p, double extent, std::vector<Vec3>& points) {
  const double reach = std::min(1.0, kBlendAllowance * extent / p.spec.surface.influence_radius) *
                       p.spec.surface.influence_radius;
  // Each glyph's points in their own place, on every core.
  constexpr std::size_t per_glyph = 14;
  const std::size_t first = points.size(), glyphs = p.glyphs.sources.size();
  reserve_on_huge_pages(points, first + per_glyph * glyphs);
  points.resize(first + per_glyph * glyphs);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, glyphs, 4096), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const GlyphSource& s = p.glyphs.sources[i];
      // The glyph is the unit ball of its gauge u, a norm symmetric in each
      // axis's sign: along a diagonal it reaches 1/u(1, 1, 1) of each axis.
      const ShapeParams& shape = shape_params(p.field, i);
      const double d = 1.0 / std::sqrt(shape_g(p.field.shape, shape, Vec3::Ones() / double(shape.bound_scale)));
      const Mat3 a = s.axes * (reach * s.radii).asDiagonal();
      Vec3* out = points.data() + first + per_glyph * i;
      for (int k = 0; k < 3; ++k) *out++ = s.centre + a.col(k), *out++ = s.centre - a.col(k);
      for (int o = 0; o < 8; ++o) *out++ = s.centre + d * a * Vec3(o & 1 ? 1 : -1, o & 2 ? 1 : -1, o & 4 ? 1 : -1);
    }
  });
}

// The points the camera frames.
std::vector<Vec3> framed_points(FrameTarget target, const PreparedScene& p, double extent) {
  std::vector<Vec3> points;
  const Box3& domain = p.glyphs.domain;
  if (target == FrameTarget::data || p.field.sources.empty()) {
    add_corners(domain, points);
    return points;
  }
  add_glyph_points(p, extent, points);
  // The outline drawn: the box's corners, or the shell's vertices, all of
  // them (the framing takes extremes: a few passes over them): a round
  // body fills the picture as its box would not, and a brain's surface
  // inside a grid of empty voxels is smaller than the grid.
  if (target == FrameTarget::drawn && p.context.box) add_corners(domain, points);
  if (target == FrameTarget::drawn && p.context.shell)
    points.insert(points.end(), p.context.shell->vertices.begin(), p.context.shell->vertices.end());
  return points;
}

// The picture's shape (width over height) when the scene does not give
// both its sides: the framed points' extent as the camera sees them,
// between 1:2 and 5:2 (a long beam gets a wide picture, a tower a tall
// one).
double body_aspect(const CameraRequest& request, const std::vector<Vec3>& framed) {
  const CameraSpec c = frame_camera(request, framed, kDefaultPixels, kDefaultPixels);
  const Vec3 forward = (c.look_at - c.position).normalized();
  const Vec3 right = forward.cross(c.up).normalized(), up = right.cross(forward);
  const std::array<double, 4> least = least_values(framed, [&](const Vec3& point) {
    const Vec3 d = point - c.position;
    const double depth = c.projection == Projection::perspective ? d.dot(forward) : 1.0;
    if (!(depth > 0.0)) return std::array<double, 4>{INFINITY, INFINITY, INFINITY, INFINITY};  // behind the camera
    const double x = d.dot(right) / depth, y = d.dot(up) / depth;
    return std::array<double, 4>{x, -x, y, -y};
  });
  const double x0 = least[0], x1 = -least[1], y0 = least[2], y1 = -least[3];
  return (x1 > x0 && y1 > y0) ? std::clamp((x1 - x0) / (y1 - y0), kTallest, kWidest) : 1.0;
}

// The picture's pixels from the one side the scene gives, the other of
// shape `aspect` (width over height).
std::array<int, 2> size_from_one_side(const SceneSpec& s, double aspect) {
  if (s.render.width) return {*s.render.width, std::max(1, int(std::lround(*s.render.width / aspect)))};
  return {std::max(1, int(std::lround(*s.render.height * aspect))), *s.render.height};
}

// The picture's pixels: as the scene gives them; a side it leaves out
// follows the body's shape from the other, and with neither the body's
// shape has the area of the default square.
std::array<int, 2> body_shaped_size(const SceneSpec& s, const CameraRequest& request, const std::vector<Vec3>& framed) {
  const double aspect = body_aspect(request, framed);
  if (s.render.width || s.render.height) return size_from_one_side(s, aspect);
  return {int(std::lround(kDefaultPixels * std::sqrt(aspect))), int(std::lround(kDefaultPixels / std::sqrt(aspect)))};
}

toml::array toml_vec3(const Vec3& v) { return toml::array{v.x(), v.y(), v.z()}; }

// Records what the field side chose for the keys it resolves
// (field/automatic_values.h), for `hsb info` to pin.
void record_field_values(PreparedScene& p) {
  const GlyphPipelineSpec& s = p.spec.pipeline;
  const GlyphValues& v = p.glyphs.values;
  if (v.singular_radius) p.resolve("data.singular_radius", *v.singular_radius);
  if (s.data.kind == DataKind::vtk_file && !p.glyphs.flow)
    p.resolve("data.quantity", p.glyphs.quantity == DataQuantity::diffusion ? "diffusion" : "stress");
  // Sources the scene gives itself (a curve, a list) have no seeds,
  // trajectories or sizes.
  if (s.data.kind == DataKind::none) return;
  if (p.glyphs.placement != SourcePlacement::at_data_points) {
    const SeedStrategy strategy = *v.seeds.strategy;
    p.resolve("seeds.strategy", strategy == SeedStrategy::even ? "even" : strategy == SeedStrategy::grid ? "grid" : "points");
    if (strategy == SeedStrategy::even) {
      p.resolve("seeds.separation", *v.seeds.separation);
      p.resolve("seeds.importance", *v.seeds.importance);
      // The seeds it took, so a pinned scene takes the same ones first.
      // Not for several families: each would take the others' seeds too,
      // and the rule alone, deterministic, gives the same lines again.
      if (v.families.size() == 1) {
        toml::array points;
        for (const Vec3& seed : v.seeds.points) points.push_back(toml_vec3(seed));
        p.resolve("seeds.points", std::move(points));
      }
    } else if (s.seeds.grids.empty() && s.seeds.points.empty()) {
      toml::array grids;
      for (const SeedGridSpec& g : v.seeds.grids)
        grids.push_back(toml::table{{"corner", toml_vec3(g.corner)}, {"edge_u", toml_vec3(g.edge_u)},
                                    {"edge_v", toml_vec3(g.edge_v)}, {"n", g.n}, {"m", g.m}});
      p.resolve("seeds.grid", std::move(grids));
    }
    // Seeds are recorded in the frame they were made in.
    p.resolve("seeds.frame", v.seeds.frame == SeedFrame::bounds ? "bounds" : "world");
  }
  if (!p.glyphs.flow && p.glyphs.placement != SourcePlacement::at_data_points)
    p.resolve("trajectories.family", family_names(v.families));
  p.resolve("trajectories.step", v.trajectory.step);
  p.resolve("trajectories.max_length", v.trajectory.max_length);
  p.resolve("trajectories.min_magnitude", v.trajectory.min_magnitude);
  p.resolve("trajectories.max_turn", v.trajectory.max_turn);
  if (v.region.above) p.resolve("region.above", *v.region.above);
  if (v.trajectory.measure) p.resolve("trajectories.stop_below", v.trajectory.min_measure);
  if (p.glyphs.placement == SourcePlacement::at_data_points) {
    p.resolve("glyphs.placement", "points");  // data without volume takes it whatever the scene says
    p.resolve("glyphs.stride", v.stride);
  } else {
    if (v.beads) p.resolve("glyphs.beads", *v.beads);
    else p.resolve("glyphs.spacing", v.spacing);
  }
  p.resolve("glyphs.scale", v.mapping.scale);
  p.resolve("glyphs.floor", v.mapping.floor);
  p.resolve("glyphs.ceiling", v.mapping.ceiling);
  p.resolve("glyphs.color_by", color_scalar_name(p.glyphs.color));
}

void warn_about_the_picture(PreparedScene& p, double extent) {
  // Glyphs larger than the data set hide it, and are usually a scale meant
  // for other units.
  const double diagonal = p.glyphs.domain.diagonal();
  std::size_t too_large = 0;
  double largest = 0.0;
  for (const GlyphSource& s : p.glyphs.sources) {
    const double size = 2.0 * extent * s.radii.maxCoeff();
    largest = std::max(largest, size);
    too_large += size > diagonal;
  }
  if (too_large) {
    std::ostringstream text;
    text << too_large << " of " << p.glyphs.sources.size() << " glyphs are larger than the whole data set (up to "
         << largest << " across, the data " << diagonal
         << "): lower glyphs.scale or glyphs.ceiling, or leave them out for automatic sizes";
    p.warnings.push_back(text.str());
  }
  // Glyphs so large that every ray crosses hundreds of their influence
  // regions make a render take hours, not seconds: say so before it starts.
  // The mean number a ray crosses is about the sum over glyphs of the
  // share of the view each one's largest cross-section covers (at most
  // all of it), at the framed distance.
  const CameraSpec& c = p.camera;
  const double aspect = c.frame_width * p.render.width / (c.frame_height * p.render.height);
  const double view_height = c.projection == Projection::perspective
                                 ? 2.0 * std::tan(0.5 * c.fov_degrees * M_PI / 180.0) * (c.look_at - c.position).norm()
                                 : c.height;
  const double view_area = view_height * view_height * aspect;
  const double R = p.spec.surface.influence_radius;
  double crossed = 0.0;
  for (const GlyphSource& s : p.glyphs.sources) {
    Vec3 r = s.radii;
    std::sort(r.data(), r.data() + 3);
    crossed += std::min(1.0, M_PI * R * r[2] * R * r[1] / view_area);
  }
  if (crossed > kCrowdedRay) {
    std::ostringstream text;
    text << "the glyphs overlap so much that a ray crosses about " << std::lround(crossed)
         << " of their influence regions: the render will be slow; lower glyphs.scale or glyphs.ceiling, or "
            "raise glyphs.spacing";
    p.warnings.push_back(text.str());
  }
  if (!p.field.sources.empty() && field_value(p.field, p.camera.position) >= p.field.isovalue)
    p.warnings.push_back("the camera is inside the surface: every ray starts inside a glyph; move camera.position "
                         "out, or leave it out to frame the glyphs from outside");
}

}  // namespace

double glyph_extent(const SurfaceSpec& surface) {
  return surface.influence_radius * kernel_level_radius(surface.kernel, surface.isovalue);
}

bool OutputSettings::streams() const {
  return !legend && !is_scene_linear_format(file) && !is_vector_format(file);
}

std::string output_file_name(const SceneSpec& spec) {
  return spec.output.file.value_or(file_stem(spec.path) + ".png");
}

std::array<int, 2> picture_size(const SceneSpec& s) {
  // As given, else the print size at the DPI; one side given beside a
  // print size, the other keeps the print's shape (a smaller proof of the
  // same figure, not a print of the wrong shape).
  const auto pixels = [&](int axis) {
    return s.output.print_size ? std::max(1, int(std::lround((*s.output.print_size)[std::size_t(axis)] / 25.4 * s.output.dpi)))
                               : kDefaultPixels;
  };
  if (s.output.print_size && (s.render.width.has_value() != s.render.height.has_value()))
    return size_from_one_side(s, (*s.output.print_size)[0] / (*s.output.print_size)[1]);
  return {s.render.width.value_or(pixels(0)), s.render.height.value_or(pixels(1))};
}

namespace {
// The direction key for the data's axes as `camera` sees them.
DirectionKey view_direction_key(const CameraSpec& camera, const std::string& anatomical_frame) {
  const Vec3 forward = (camera.look_at - camera.position).normalized(), right = forward.cross(camera.up).normalized();
  return direction_key(right, right.cross(forward), anatomical_frame);
}
}  // namespace

LegendLayout legend_for(const PreparedScene& p, int width, int height) {
  const OutputSpec& o = p.spec.output;
  LegendStyle style;
  style.placement = o.colorbar_position;
  style.font_size = o.font_size;
  style.length = o.colorbar_length;
  style.dpi = o.dpi;
  LegendContent content;
  content.bar = p.glyphs.color != ColorScalar::none && p.glyphs.color != ColorScalar::direction;
  if (p.glyphs.color == ColorScalar::direction)
    content.direction = view_direction_key(p.camera, p.glyphs.anatomical_frame);
  content.title = o.colorbar_title.value_or(scalar_title(p.glyphs.color, p.spec));
  // Stress of both signs: the bar's ends say which is which.
  if (content.bar && carries_stress_sign(p.glyphs.color) && !p.scale.log && p.scale.lo < 0.0 && p.scale.hi > 0.0) {
    const bool tension_high = p.spec.pipeline.data.sign == SignConvention::tension_positive;
    content.high_word = tension_high ? "tension" : "compression";
    content.low_word = tension_high ? "compression" : "tension";
  }
  if (wants_shape_key(p.spec)) content.key = signed_shape_key(p.spec.surface.sharpness);
  return layout_legend(p.scale, content, style, width, height);
}

bool wants_shape_key(const SceneSpec& spec) {
  return spec.output.shape_key.value_or(spec.surface.shape == GlyphShape::signed_superquadric);
}

// Source i's sRGB colour on `scale`.
Rgb source_srgb(const PreparedScene& p, const ColorScale& scale, std::size_t i) {
  const GlyphSource& g = p.glyphs.sources[i];
  if (p.glyphs.color == ColorScalar::direction) return direction_srgb(g.axes.col(0), g.scalar);
  return p.glyphs.color == ColorScalar::none ? kUncoloured : scale.srgb(g.scalar);
}

void set_color_scale(PreparedScene& p, const ColorScale& scale, const ColorManagement& color) {
  p.scale = scale;
  for (std::size_t i = 0; i < p.field.sources.size(); ++i)
    p.field.sources[i].color = color.to_scene_linear(source_srgb(p, scale, i));
}

ColorManagement scene_color_management(const SceneSpec& spec) {
  const OutputSpec& o = spec.output;
  try {
    return ColorManagement(o.display.value_or(""), o.view.value_or(""), o.ocio_config);
  } catch (const std::exception& e) {
    throw SceneError(spec.path + ": output.display/output.view/output.ocio_config: " + e.what());
  }
}

std::unique_ptr<PreparedScene> prepare_scene(SceneSpec spec, const ColorManagement& color) {
  // Before any thread starts: TBB's reading and tracing, Pango's legend.
  fit_threads_to_room();
  auto prepared = std::make_unique<PreparedScene>();
  PreparedScene& p = *prepared;
  p.spec = std::move(spec);
  const SceneSpec& s = p.spec;

  // The field side resolves its own automatic values from the data and
  // the trajectories (field/automatic_values.h). The scene's lengths are
  // checked against the data's size as soon as it is known.
  const double extent = glyph_extent(s.surface);
  p.glyphs = build_glyph_scene(s.pipeline, extent, [&](const Box3& domain) { check_data_lengths(s, domain.diagonal()); });
  p.warnings = p.glyphs.warnings;
  // A diffusion volume's glyph field: superquadrics, which tell a line
  // from a disc where ellipsoids blur them (Kindlmann), as Teem draws it.
  // (Not where the scene asks for the exact intersector, ellipsoids' own.)
  if (!s.surface.shape_given && p.glyphs.quantity == DataQuantity::diffusion &&
      p.glyphs.placement == SourcePlacement::at_data_points && s.render.intersector != Intersector::exact)
    p.spec.surface.shape = GlyphShape::superquadric;
  p.resolve("glyphs.shape", glyph_shape_name(s.surface.shape));
  record_field_values(p);
  const Box3& domain = p.glyphs.domain;
  const double diagonal = domain.diagonal();

  p.scale = color_scale(s, p.glyphs);
  p.resolve("color.map", p.scale.map->name);
  p.resolve("color.range", toml::array{p.scale.lo, p.scale.hi});
  std::vector<std::array<float, 3>> colors;
  colors.reserve(p.glyphs.sources.size());
  for (std::size_t i = 0; i < p.glyphs.sources.size(); ++i)
    colors.push_back(color.to_scene_linear(source_srgb(p, p.scale, i)));
  p.field = make_blob_field(p.glyphs.sources, colors, s.surface.influence_radius, s.surface.kernel, s.surface.blend,
                            s.surface.isovalue, s.surface.shape, s.surface.sharpness, s.pipeline.data.sign);

  // A box frames an analytic domain, a shell shows a mesh's boundary;
  // sources the scene gives itself have neither.
  const bool has_boundary = p.glyphs.boundary.has_value();
  if (p.resolve("render.box", s.context.box.value_or(s.pipeline.data.kind == DataKind::point_load))) p.context.box = domain;
  p.context.box_radius = p.resolve("render.box_radius", s.context.box_radius.value_or(kBoxRadiusPerDiagonal * diagonal));
  if (p.resolve("render.shell", s.context.shell.value_or(has_boundary) && has_boundary)) p.context.shell = &*p.glyphs.boundary;

  // Lengths that follow the glyphs: a median glyph's size.
  const double glyph = median_glyph_size(p.glyphs.sources, extent, diagonal);
  p.context.glyphs = s.context.glyphs;
  if (s.context.trajectories) {
    for (const Trajectory& t : p.glyphs.trajectories) p.context.trajectories.push_back(&t.points);
    p.context.trajectory_radius = p.resolve("render.trajectory_radius", s.context.trajectory_radius.value_or(kTubePerGlyph * glyph));
  }

  p.shading = s.shading;
  p.shading.background = color.to_scene_linear(p.shading.background);
  p.shading.background_bottom = color.to_scene_linear(p.shading.background_bottom);
  p.shading.box_color = color.to_scene_linear(p.shading.box_color);
  p.shading.shell_color = color.to_scene_linear(p.shading.shell_color);
  p.shading.trajectory_color = color.to_scene_linear(p.shading.trajectory_color);
  p.shading.ao_distance = s.light.ao_distance.value_or(kOcclusionPerGlyph * glyph);
  if (s.shading.ao_samples > 0) p.resolve("light.ambient_occlusion.distance", p.shading.ao_distance);

  CameraRequest camera = s.camera;
  if (!camera.view) camera.view = automatic_view(domain, p.glyphs.plane_axis);
  const std::vector<Vec3> framed = framed_points(s.camera.frame, p, extent);
  const bool shaped = !(s.render.width && s.render.height) && !s.output.print_size;
  const std::array<int, 2> size = shaped ? body_shaped_size(s, camera, framed) : picture_size(s);
  p.render.width = s.render.width.value_or(size[0]);
  p.render.height = s.render.height.value_or(size[1]);
  p.render.samples = s.render.samples;
  // Exact wherever it applies: it was the faster of the two over the
  // figure scenes, and exact; blinn summed has no polynomial form.
  p.trace.intersector = s.render.intersector.value_or(
      exact_crossing_supported(s.surface.kernel, s.surface.blend, s.surface.shape) ? Intersector::exact
                                                                                    : Intersector::sphere);
  p.resolve("render.intersector", p.trace.intersector == Intersector::exact ? "exact" : "sphere");
  p.trace.min_step = p.resolve("render.min_step", s.render.min_step.value_or(kMinStepPerDiagonal * diagonal));
  p.trace.max_steps = s.render.max_steps;

  p.output.file = p.resolve("output.file", output_file_name(s));
  const bool exr = is_scene_linear_format(p.output.file);
  p.output.bit_depth = p.resolve("output.bit_depth", s.output.bit_depth.value_or(exr ? 32 : 8));
  p.output.dpi = s.output.dpi;
  if (exr) p.render.planes = s.output.layers;
  PictureReserve reserve;
  // No colour, no colour bar; the shape key may stand alone.
  const bool key = p.resolve("output.shape_key", wants_shape_key(s));
  if (s.output.colorbar && !p.field.sources.empty() && !exr && (p.glyphs.color != ColorScalar::none || key)) {
    p.output.legend = legend_for(p, p.render.width, p.render.height);
    if (shaped) {
      // The legend's part is added to the body's shape, not taken from
      // it: the side it lies along grows, or where the scene gave that
      // side, the other shrinks.
      const bool right = p.output.legend->style.placement == LegendPlacement::right;
      const double free = 1.0 - p.output.legend->reserved;
      if (!(right ? s.render.width : s.render.height)) {
        int& grown = right ? p.render.width : p.render.height;
        grown = int(std::lround(grown / free));
      } else {
        int& shrunk = right ? p.render.height : p.render.width;
        shrunk = std::max(1, int(std::lround(shrunk * free)));
      }
      p.output.legend = legend_for(p, p.render.width, p.render.height);
    }
    if (p.output.legend->bar) p.resolve("output.colorbar_title", p.output.legend->title);
    (p.output.legend->style.placement == LegendPlacement::right ? reserve.right : reserve.bottom) =
        p.output.legend->reserved;
  }

  p.resolve("render.width", p.render.width);
  p.resolve("render.height", p.render.height);
  std::ostringstream picture;
  picture << "the scene with its picture (" << p.render.width << " × " << p.render.height << " pixels)";
  // The image module loads while the data is read (image_io_module.h),
  // and counts towards the peak: what is resident holds the sources, made
  // by now, and what of the module has loaded; the rest of it is added,
  // and what the render builds for each source.
  // (The render goes on beside the load; the picture is written after it.)
  const double held =
      std::max(p.glyphs.memory_estimate, resident_bytes() + kRenderBytesPerSource * double(p.field.sources.size())) +
      image_io_pending_bytes();
  p.memory_estimate =
      held + (p.output.streams() ? kStreamedBytesPerPixel : kBytesPerPixel) * p.render.width * p.render.height;
  check_memory(p.memory_estimate, picture.str(),
               "lower render.width and render.height (or output.print_size or output.dpi)");
  p.camera = frame_camera(camera, framed, p.render.width, p.render.height, reserve);
  // The legend was laid out before the camera was framed (its part of the
  // picture is kept from the view): its axes are the view's.
  if (p.output.legend && p.output.legend->direction)
    p.output.legend->direction = view_direction_key(p.camera, p.glyphs.anatomical_frame);
  p.resolve("camera.position", toml_vec3(p.camera.position));
  p.resolve("camera.look_at", toml_vec3(p.camera.look_at));
  p.resolve("camera.up", toml_vec3(p.camera.up));
  if (p.camera.projection == Projection::orthographic) p.resolve("camera.height", p.camera.height);
  const Box3 framed_box = bounding_box(framed);
  // (Nothing drawn: the data's box.)
  const Box3 drawn = framed_box.lo.allFinite() && framed_box.hi.allFinite() ? framed_box : domain;
  p.render.shadow_offset = p.resolve(
      "render.shadow_offset",
      s.render.shadow_offset.value_or(kShadowOffsetPerPixel * Camera(p.camera, p.render.width, p.render.height)
                                                                   .pixel_size_at(drawn.centre())));
  p.shading.ground = s.context.ground;
  p.shading.ground_height = s.context.ground_height.value_or(drawn.lo.z());
  if (s.context.ground) p.resolve("render.ground_height", p.shading.ground_height);

  warn_about_the_picture(p, extent);
  return prepared;
}

}  // namespace hsb
