#pragma once
// The whole field side of a scene in one call: data set → seeds →
// trajectories → sources. The renderer fills a GlyphPipelineSpec from a scene
// file and receives sources; it never touches a data set itself.
//
// A spec says what the scene file says: a value it leaves out is
// std::nullopt, "automatic", never a magic number. build_glyph_scene()
// resolves every automatic value from the data and the trajectories, by the
// rules of automatic_values.h, and hands back the values it used
// (GlyphValues), so they can be shown and pinned.

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "field/data_quantity.h"
#include "field/glyphs/curve_sources.h"
#include "field/glyphs/glyph_sources.h"
#include "field/glyphs/sign_convention.h"
#include "field/glyphs/triangle_mesh.h"
#include "field/reading/vtk_data.h"
#include "field/sampling/point_load.h"
#include "field/tensor/tensor_measures.h"
#include "field/tracing/trajectory.h"

namespace hsb {

// none: the sources come from the scene (a curve, a list), no data is read.
enum class DataKind { point_load, vtk_file, none };

struct DataSpec {
  DataKind kind = DataKind::point_load;
  PointLoadSpec point_load;
  VtkFileSpec file;
  // When all three are ≥ 2, the data set is sampled onto a grid of these
  // dimensions spanning its bounds, and everything downstream reads the grid.
  std::array<int, 3> sample_grid{0, 0, 0};
  SignConvention sign = SignConvention::tension_positive;
  // Automatic: recognised from the tensors (data_quantity.h).
  std::optional<DataQuantity> quantity;
};

struct SeedGridSpec {
  Vec3 corner = Vec3::Zero();
  Vec3 edge_u = Vec3::UnitX();
  Vec3 edge_v = Vec3::UnitY();
  int n = 3;
  int m = 3;
};

// The coordinates seeds are given in.
enum class SeedFrame {
  world,   // the data's own coordinates
  bounds,  // fractions of the data's bounding box: (0,0,0) its low corner,
           // (1,1,1) its high corner, so a scene fits any data set
};

// How seeds are chosen.
enum class SeedStrategy {
  even,    // evenly spaced trajectories filling the body (field/tracing/even_seeding.h);
           // `points`, if any, are taken first
  grid,    // the `grids` (automatic: a 5×5 grid across the body's middle)
  points,  // the `points` and `grids` as given
};

struct SeedSpec {
  // Automatic: even, unless points or grids are given (then those alone).
  std::optional<SeedStrategy> strategy;
  std::vector<Vec3> points;
  std::vector<SeedGridSpec> grids;
  SeedFrame frame = SeedFrame::world;
  // even: the separation d_sep between trajectories (automatic: from the
  // body's size), and whether it follows the magnitude (automatic: for
  // tensors, not for a flow).
  std::optional<double> separation;
  std::optional<bool> importance;

  bool automatic() const { return !strategy && points.empty() && grids.empty(); }
  SeedStrategy resolved_strategy() const {
    if (strategy) return *strategy;
    return points.empty() && grids.empty() ? SeedStrategy::even : SeedStrategy::points;
  }
};

// The part of the data the picture keeps to, where the structure is
// (a diffusion volume's fibres, FA > 0.3): seeds are taken, lines run and
// glyphs at data points stand only where `measure` (a colour scalar of the
// tensor, glyph_mapping.h) is at least `above`. None: everywhere.
// A mask (a brain mask, a region of interest) narrows it further: only
// where the mask's value is at least ½, a binary mask's voxels and half the
// way between them and the voxels outside.
struct RegionSpec {
  ColorScalar measure = ColorScalar::fa;
  std::optional<double> above;
  // "array:NAME", a scalar array of the data file, or a file of its own
  // (load_mask); "": none.
  std::string mask;
  std::shared_ptr<const ScalarField> mask_field;  // the mask, once read

  static constexpr const char* kMaskArrayPrefix = "array:";
  bool restricts() const { return above || mask_field; }
  bool in_mask(const Vec3& x) const {
    if (!mask_field) return true;
    const std::optional<double> value = mask_field->sample(x);
    return value && *value >= 0.5;
  }
  bool holds(const Vec3& x, const Vec3& eigenvalues) const {
    return in_mask(x) && (!above || color_scalar(eigenvalues, measure) >= *above);
  }
  // Whether the tensor's components alone show it below (above) the
  // threshold, before any decomposition: most of a diffusion volume lies
  // well below its FA threshold, and a tract's voxels well above it. Near
  // it (within 1e-9, far beyond the round-off between the components' FA
  // and the eigenvalues') holds() decides, so the region is the same
  // either way. Other measures: never.
  bool surely_below(const Sym3& tensor) const {
    return fa_threshold() && fractional_anisotropy(tensor) < *above - kFaMargin;
  }
  bool surely_above(const Sym3& tensor) const {
    return fa_threshold() && fractional_anisotropy(tensor) > *above + kFaMargin;
  }

 private:
  static constexpr double kFaMargin = 1e-9;
  bool fa_threshold() const { return above && measure == ColorScalar::fa; }
};

// The scene's [trajectories]; what it leaves out is automatic.
struct TrajectorySpec {
  // The families traced, each with lines of its own. Automatic (empty):
  // major and minor for tensors seeded evenly (tension and compression
  // lines, each coloured by its own eigenvalue), major otherwise.
  std::vector<EigenFamily> families;
  std::optional<double> step, max_length;
  double degeneracy_tolerance = 1e-3;
  // Automatic: 0 for tensors; for a flow, a thousandth of its largest
  // speed (stagnation: the direction means nothing there).
  std::optional<double> min_magnitude;
  int max_steps = 100000;
  TraceDirection direction = TraceDirection::both;
  std::optional<double> max_turn;  // degrees per step; automatic: no limit
  // Weinstein's tensorlines instead of the eigenvector (TrajectoryOptions).
  bool tensorlines = false;
  double puncture = 0.5;
  // Lines end where the region's measure falls below this (automatic: the
  // region's own threshold, its edge): seeds in the fibres' core, lines
  // followed out to their fringe, as tractography seeds and stops.
  std::optional<double> stop_below;
};

// How eigenvalues become radii; scale, floor and ceiling left out are
// automatic. The square root by default: on data nobody has looked at yet,
// it shows the small stresses as well as the large (the paper's Figure 6
// against Figure 5) while large ones still blend and small ones separate.
struct GlyphSizeSpec {
  RadiusMapping mapping = RadiusMapping::sqrt;
  std::optional<double> scale, floor, ceiling;
};

enum class SourcePlacement {
  along_trajectories,  // hyperstreamballs: sources spaced along tensor lines (streamballs: streamlines)
  at_seeds,            // one glyph per seed point: classic ellipsoid glyphs
  at_data_points,      // one glyph at each data point (or cell centre), with a stride: the discrete glyph field
  curve,               // along a curve the scene gives, one fixed shape (no data)
  list,                // as listed in a CSV file (no data)
};

struct GlyphPipelineSpec {
  DataSpec data;
  RegionSpec region;
  SeedSpec seeds;
  TrajectorySpec trajectory;
  SourcePlacement placement = SourcePlacement::along_trajectories;
  std::optional<double> spacing;  // arc length between sources
  // Glyphs end to end along each trajectory instead (BeadRule): how much
  // neighbours overlap, a fraction of their lengths. Automatic: 0 (tip to
  // tip) when the glyphs' shape shows the sign (`signed_shapes`) and no
  // spacing is given, as the sign of a line's own eigenvalue shows only at
  // the glyphs' ends, which blending at a spacing would bury; else none.
  std::optional<double> beads;
  bool signed_shapes = false;
  std::optional<int> stride;      // placement points: every stride-th data point
  GlyphSizeSpec size;
  // Automatic: the traced family's eigenvalue (major: λ1) for tensors, the
  // speed for a flow.
  // ColorScalar::array colours by data.file.color_array.
  std::optional<ColorScalar> color;
  double stretch = 1.0;  // streamballs: the first radius (along the flow) times this
  // 2-D data: the glyphs' thickness across the plane; none: each glyph's
  // smaller in-plane diameter (flatten_sources).
  std::optional<double> thickness;
  CurveSpec curve;        // placement curve
  std::string list_file;  // placement list: the CSV file (source_list.h)
};

// Every field-side value the pipeline used, automatic ones resolved.
struct GlyphValues {
  std::optional<double> singular_radius;  // the point load's; none for files
  RegionSpec region;
  // Resolved: the strategy is set; for even seeding, the separation, the
  // importance and the seeds taken (as points, in the frame given), so
  // they can be shown and pinned.
  SeedSpec seeds;
  double reference_magnitude = 0.0;  // even seeding's median magnitude
  TrajectoryOptions trajectory;  // its family: the first traced
  std::vector<EigenFamily> families;  // every family traced, resolved
  double spacing = 0.0;
  std::optional<double> beads;  // resolved: none when sources are spaced by `spacing`
  int stride = 1;  // placement points
  GlyphMapping mapping;
};

struct GlyphScene {
  Box3 domain;
  SourcePlacement placement = SourcePlacement::along_trajectories;  // resolved: data without volume takes points
  bool flow = false;  // made from a vector field (streamballs), not tensors
  DataQuantity quantity = DataQuantity::stress;  // resolved (a flow's: stress, unused)
  ColorScalar color = ColorScalar::lambda3;  // what `scalar` holds, resolved
  std::vector<Trajectory> trajectories;
  std::vector<GlyphSource> sources;
  std::optional<TriangleMesh> boundary;  // a mesh's outer surface (none for analytic data)
  std::optional<int> plane_axis;         // a 2-D result: its plane's normal axis (seen along it)
  // The colour scalar's extremes over the data's own values, which the
  // glyphs may not reach (field/glyphs/data_extremes.h); none where the
  // data has no values of its own or the colour is not the tensor's.
  std::optional<std::array<double, 2>> color_extremes;
  std::vector<double> color_sample;  // the same scalar at some of the data's points (data_color_sample)
  std::string anatomical_frame;          // where the axes point ("RAS"), where the file says; else ""
  GlyphValues values;
  std::vector<std::string> warnings;     // about the data, for the user
  // The peak resident memory this scene will take once rendered, the
  // picture aside: the process's size before its sources were made, and
  // what each source costs through to the render.
  double memory_estimate = 0.0;
};

struct LoadedField {
  std::unique_ptr<TensorField> field;    // tensor data; or
  std::unique_ptr<VectorField> vectors;  // a flow
  std::unique_ptr<ScalarField> color;    // data.file.color_array, when named
  std::unique_ptr<ScalarField> mask;     // data.file.mask_array, when named
  double max_speed = 0.0;                // of the flow's values
  std::optional<TriangleMesh> boundary;
  std::optional<int> plane_axis;  // a 2-D result (field/reading/vtk_data.h)
  std::string anatomical_frame;   // "RAS", "LPS" where the format says (field/reading/vtk_data.h)
  std::vector<std::string> warnings;
  DataSites sites;        // the data's values where they stand (placement points, data without volume)
  std::string no_volume;  // why the data has no volume to trace in ("": it has)
  std::optional<DataQuantity> quantity;  // a data file's tensors': given or recognised (VtkData::quantity)
};

// Builds (or reads) the data set described by `spec`. Throws DataError for
// unusable data files.
LoadedField make_field(const DataSpec& spec);

// The values an automatic colour range spans: the glyphs' scalars, and
// the data's own (its sample and extremes), so that a stress
// concentration the lines do not reach (a notch's or a hole's edge) is
// coloured near its peak, unless the range's fence finds it singular
// (renderer/image/colormap.h: auto_scale).
std::vector<double> color_range_values(const GlyphScene& scene);

// Where build_glyph_scene() puts the glyphs of traced placements. A time
// series' steps lend only their magnitudes and colours to the settings
// its images share (renderer/app/series_scale.h); tracing each of 5,000
// steps for that took 45 minutes before any image. The lattice that
// measures the body samples the same glyphs, evenly, with no line traced.
enum class GlyphPlacing {
  as_specified,    // as the scene says
  on_body_lattice  // one glyph of each family at each point of the body's lattice, where the scene traces
};

// Runs the pipeline. `glyph_extent` is an isolated glyph's largest
// semi-axis for a largest radius of 1 (the renderer's influence radius R
// times its kernel's level radius): the automatic glyph size is a length in
// the data's units, so it must know how radii turn into lengths.
// Trajectories are traced in parallel and the result does not depend on the
// thread count. `with_domain`, when given, is called with the data's
// bounds as soon as they are known, before any trajectory is traced (the
// renderer checks the scene's lengths against them there).
// `placing` on_body_lattice: no trajectory is traced (nor any warning
// about them given); the mapping is made as for the traced glyphs.
GlyphScene build_glyph_scene(const GlyphPipelineSpec& spec, double glyph_extent,
                             const std::function<void(const Box3& domain)>& with_domain = {},
                             GlyphPlacing placing = GlyphPlacing::as_specified);

}  // namespace hsb
