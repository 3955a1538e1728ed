#include "field/glyph_pipeline.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include <tbb/parallel_for.h>

#include "base/memory_budget.h"
#include "base/process_memory.h"
#include "field/automatic_values.h"
#include "field/glyphs/source_list.h"
#include "field/glyphs/data_extremes.h"
#include "field/reading/data_error.h"
#include "field/sampling/mesh_field.h"
#include "field/sampling/uniform_grid.h"
#include "field/tensor/eigensystem.h"
#include "field/tracing/even_seeding.h"
#include "field/tracing/seeding.h"

namespace hsb {

LoadedField make_field(const DataSpec& spec) {
  LoadedField loaded;
  if (spec.kind == DataKind::vtk_file) {
    VtkFileSpec file = spec.file;
    file.quantity = spec.quantity;
    VtkData data = load_vtk_data(file);
    loaded.field = std::move(data.field);
    loaded.vectors = std::move(data.vectors);
    loaded.color = std::move(data.color);
    loaded.mask = std::move(data.mask);
    loaded.boundary = std::move(data.boundary);
    loaded.plane_axis = data.plane_axis;
    loaded.anatomical_frame = data.anatomical_frame;
    loaded.warnings = std::move(data.warnings);
    loaded.sites = std::move(data.sites);
    loaded.no_volume = std::move(data.no_volume);
    loaded.quantity = data.quantity;
    if (const auto* mesh = dynamic_cast<const MeshField<Vec3>*>(loaded.vectors.get()))
      for (const Vec3& v : mesh->values()) loaded.max_speed = std::max(loaded.max_speed, v.norm());
  } else {
    loaded.field = std::make_unique<PointLoadField>(spec.point_load);
  }
  const auto& dims = spec.sample_grid;
  if (loaded.field && loaded.no_volume.empty() && std::all_of(dims.begin(), dims.end(), [](int d) { return d >= 2; })) {
    // A tensor a node while sampling, and as much again while the grid is
    // moved into place.
    const double nodes = double(dims[0]) * double(dims[1]) * double(dims[2]);
    std::ostringstream what;
    what << "the sampled grid (" << dims[0] << " × " << dims[1] << " × " << dims[2] << " nodes)";
    check_memory(2.0 * nodes * double(sizeof(Sym3)), what.str(), "use a coarser data.sample_grid");
    loaded.field = std::make_unique<UniformGridField>(UniformGridField::sampled_from(*loaded.field, dims));
  }
  return loaded;
}

namespace {

// Memory a trajectory point and a glyph source take, all copies included
// (a point: its position, with the vector's growth; a source: the field's
// and the renderer's copies, the span BVH's share, the per-trajectory
// lists it passes through and the allocator's slack). A source's was
// measured as the growth of the peak resident size between fig09 at
// glyphs.spacing 0.004, 0.002 and 0.001 (27,516 to 110,004 sources):
// 1,200 to 1,240 bytes; tests/cli/memory_test.sh holds the estimate to
// within 25 % of the peak.
constexpr double kBytesPerTrajectoryPoint = 48.0;
constexpr double kBytesPerSource = 1250.0;

// Glyphs of each family sampled on the body's lattice in place of traced
// ones (GlyphPlacing::on_body_lattice): the automatic mapping's
// percentile of 4,096 values lies within 1.5 % of the rank of the whole's.
constexpr std::size_t kLatticeGlyphs = 4096;

std::size_t seed_count(const SeedSpec& spec) {
  double n = double(spec.points.size());
  for (const SeedGridSpec& g : spec.grids) n += double(g.n) * double(g.m);
  return std::size_t(n);
}

// Before the seeds are even made: the seeds and the longest trajectories
// they could grow must fit in memory.
void check_seed_and_trajectory_memory(const GlyphValues& values, SourcePlacement placement) {
  const double seeds = double(seed_count(values.seeds)) * double(values.families.size());  // a line per family
  std::ostringstream what;
  if (placement == SourcePlacement::at_seeds) {
    what << "the glyphs (one at each of " << std::size_t(seeds) << " seeds)";
    check_memory(seeds * kBytesPerSource, what.str(), "use fewer seeds (seeds.points, seeds.grid n and m)");
    return;
  }
  const TrajectoryOptions& t = values.trajectory;
  const double points = 2.0 * (std::min(double(t.max_steps), std::ceil(t.max_length / t.step)) + 1.0);
  what << "the trajectories (" << std::size_t(seeds) << " seeds, each up to " << std::size_t(points)
       << " points at trajectories.step "
       << t.step << ")";
  check_memory(seeds * points * kBytesPerTrajectoryPoint, what.str(),
               "use fewer seeds (seeds.points, seeds.grid n and m), a larger trajectories.step, or a smaller "
               "trajectories.max_length or trajectories.max_steps");
}

std::vector<Vec3> all_seeds(const SeedSpec& spec, const Box3& bounds) {
  std::vector<Vec3> seeds = spec.points;
  for (const SeedGridSpec& g : spec.grids) {
    const std::vector<Vec3> grid = grid_seeds(g.corner, g.edge_u, g.edge_v, g.n, g.m);
    seeds.insert(seeds.end(), grid.begin(), grid.end());
  }
  if (spec.frame == SeedFrame::bounds) {
    for (Vec3& s : seeds) s = bounds.lo + bounds.size().cwiseProduct(s);
  }
  return seeds;
}

// The field-side values that depend on the data set's size only (and, for
// a flow, its largest speed).
// `separation`: evenly spaced seeding's, when it applies.
GlyphValues resolve_lengths(const GlyphPipelineSpec& spec, const Box3& domain, const LoadedField& loaded,
                            std::optional<double> separation, const std::vector<EigenFamily>& families,
                            DataQuantity quantity) {
  GlyphValues v;
  v.seeds = spec.seeds;
  v.seeds.strategy = spec.seeds.resolved_strategy();
  if (*v.seeds.strategy == SeedStrategy::grid && v.seeds.grids.empty() && v.seeds.points.empty()) {
    v.seeds = automatic_seeds(domain, loaded.plane_axis);
    v.seeds.strategy = SeedStrategy::grid;
  }
  if (separation) {
    v.seeds.separation = separation;
    // Diffusivity says nothing of where the fibres matter: lines as dense
    // in a faint bundle as in a strong one.
    v.seeds.importance =
        spec.seeds.importance.value_or(loaded.vectors == nullptr && quantity != DataQuantity::diffusion);
  }
  TrajectoryOptions& t = v.trajectory;
  t.family = families.front();
  v.families = families;
  t.step = spec.trajectory.step.value_or(automatic_step(domain, separation));
  t.max_length = spec.trajectory.max_length.value_or(automatic_max_length(domain));
  t.degeneracy_tolerance = spec.trajectory.degeneracy_tolerance;
  t.min_magnitude = spec.trajectory.min_magnitude.value_or(loaded.vectors ? 1e-3 * loaded.max_speed : 0.0);
  t.max_steps = spec.trajectory.max_steps;
  t.direction = spec.trajectory.direction;
  t.max_turn = spec.trajectory.max_turn.value_or(180.0);
  t.tensorlines = spec.trajectory.tensorlines;
  t.puncture = spec.trajectory.puncture;
  t.signed_directions = loaded.vectors != nullptr;
  v.spacing = spec.spacing.value_or(automatic_spacing(domain, spec.size.mapping, separation));
  if (spec.placement == SourcePlacement::along_trajectories)
    v.beads = spec.beads ? spec.beads : spec.signed_shapes && !spec.spacing ? std::optional<double>(0.0) : std::nullopt;
  return v;
}

// The sources of every trajectory as beads (BeadRule), once the mapping
// that sizes them is known. `extent` turns a radius along the line into a
// length (for a flow, with the stretch along it); where no glyph can be
// made the walk steps on by `spacing`. The count is bounded before any is
// made: no bead is shorter than the floor allows.
template <typename Maker>
std::vector<GlyphSource> beads_along(const std::vector<Trajectory>& trajectories, double overlap,
                                     const GlyphMapping& mapping, double extent, double spacing, const Maker& maker) {
  const double least_step = 2.0 * (1.0 - overlap) * extent * mapping.floor;
  double count = 0.0;
  for (const Trajectory& t : trajectories) count += t.points.empty() ? 0.0 : t.length() / least_step + 1.0;
  std::ostringstream what;
  what << "the glyph sources (up to " << std::setprecision(count < 1e15 ? 15 : 3) << std::floor(count)
       << " beads along " << trajectories.size() << " trajectories at glyphs.floor " << mapping.floor << ")";
  check_memory(resident_bytes() + count * kBytesPerSource, what.str(), "raise glyphs.floor or glyphs.beads");
  std::vector<std::vector<GlyphSource>> per_line(trajectories.size());
  tbb::parallel_for(std::size_t{0}, per_line.size(), [&](std::size_t i) {
    const int along = int(trajectories[i].family);  // the followed eigenvector's axis
    BeadRule rule;
    rule.overlap = overlap;
    rule.least_step = std::min(least_step, spacing);
    rule.half_length = [&, along](const GlyphSource& s) { return extent * map_radii(s.eigenvalues, mapping)[along]; };
    per_line[i] = place_beads(trajectories[i], rule, maker(trajectories[i].family));
  });
  std::vector<GlyphSource> sources;
  for (std::vector<GlyphSource>& line : per_line) sources.insert(sources.end(), line.begin(), line.end());
  return sources;
}

const char* stop_name(StopReason r) {
  switch (r) {
    case StopReason::boundary: return "the boundary";
    case StopReason::max_length: return "trajectories.max_length";
    case StopReason::degenerate: return "a degenerate point (repeated eigenvalues)";
    case StopReason::low_magnitude: return "trajectories.min_magnitude (or a stagnation point of a flow)";
    case StopReason::max_steps: return "trajectories.max_steps";
    case StopReason::closed: return "its own start (a closed curve)";
    case StopReason::too_close: return "another trajectory (seeds.separation)";
    case StopReason::left_region: return "the region's edge (region.above, region.mask)";
    case StopReason::sharp_turn: return "a turn sharper than trajectories.max_turn";
  }
  return "?";
}

// What helps where the followed eigenvector is undefined, from which
// eigenvalues the glyphs show equal (within the degeneracy tolerance).
std::string degeneracy_advice(const GlyphScene& scene) {
  const double tolerance = scene.values.trajectory.degeneracy_tolerance;
  std::size_t upper = 0, lower = 0, all = 0;
  for (const GlyphSource& s : scene.sources) {
    const Vec3& l = s.eigenvalues;
    const double m = l.cwiseAbs().maxCoeff();
    const bool top = l(0) - l(1) <= tolerance * m, bottom = l(1) - l(2) <= tolerance * m;
    all += top && bottom, upper += top && !bottom, lower += bottom && !top;
  }
  if (all >= upper && all >= lower)
    return "the stress is isotropic (λ1 = λ2 = λ3) there, so no direction exists: its glyphs are spheres; "
           "show sizes with glyphs.placement = \"points\", or colour by another quantity";
  const EigenFamily family = scene.values.trajectory.family;
  if (upper >= lower)
    return family == EigenFamily::minor
               ? "λ1 = λ2 there, which the minor family does not mind: seed it where it is not degenerate (seeds.points)"
               : "λ1 = λ2 there (a uniaxial compression, or a plane's unloaded direction): trace "
                 "trajectories.family = \"minor\", whose λ3 stands apart, or seed elsewhere (seeds.points)";
  return family == EigenFamily::major
             ? "λ2 = λ3 there, which the major family does not mind: seed it where it is not degenerate (seeds.points)"
             : "λ2 = λ3 there (a uniaxial tension, or a plane's unloaded direction): trace "
               "trajectories.family = \"major\", whose λ1 stands apart, or seed elsewhere (seeds.points)";
}

// An empty or nearly empty picture deserves a reason.
void warn_about_the_result(GlyphScene& scene, std::size_t seeds) {
  if (scene.sources.empty() && scene.placement == SourcePlacement::at_data_points) {
    scene.warnings.push_back("no glyph sources: no data point (of those glyphs.stride keeps) has a value there");
    return;
  }
  if (scene.sources.empty() && seeds == 0) {
    scene.warnings.push_back("no glyph sources: no seed lies inside the data set where it can be sampled");
    return;
  }
  if (scene.sources.empty()) {
    scene.warnings.push_back("no glyph sources: none of the " + std::to_string(seeds) +
                             " seeds lies inside the data set where it can be sampled");
    return;
  }
  if (scene.trajectories.empty()) return;
  const double step = scene.values.trajectory.step;
  const std::size_t at_degenerate = std::size_t(std::count_if(
      scene.trajectories.begin(), scene.trajectories.end(), [&](const Trajectory& t) {
        return t.length() <= step && t.forward_stop == StopReason::degenerate;
      }));
  const bool any_long = std::any_of(scene.trajectories.begin(), scene.trajectories.end(),
                                    [&](const Trajectory& t) { return t.length() > step; });
  if (any_long) {
    // Lines where the field has a direction, lone glyphs elsewhere: fine,
    // unless the lone glyphs are most of the picture.
    if (2 * at_degenerate > scene.trajectories.size()) {
      std::ostringstream text;
      text << at_degenerate << " of " << scene.trajectories.size()
           << " seeds stand alone at a degenerate point (repeated eigenvalues): " << degeneracy_advice(scene);
      scene.warnings.push_back(text.str());
    }
    return;
  }
  // Say where they stopped: the most common reason is the one to act on.
  std::array<int, kStopReasons> reasons{};
  for (const Trajectory& t : scene.trajectories) {
    ++reasons[std::size_t(t.backward_stop)];
    ++reasons[std::size_t(t.forward_stop)];
  }
  const auto most = std::size_t(std::max_element(reasons.begin(), reasons.end()) - reasons.begin());
  std::ostringstream text;
  text << "no trajectory is longer than one step (" << step << "); most stop at "
       << stop_name(StopReason(most)) << ": each glyph stands alone at its seed";
  if (StopReason(most) == StopReason::degenerate) text << "; " << degeneracy_advice(scene);
  scene.warnings.push_back(text.str());
}

}  // namespace

namespace {

// The colour scalar, resolved: the traced family's eigenvalue for tensors
// and the speed for a flow by default; one that the data cannot give is
// an error.
ColorScalar resolve_color(const GlyphPipelineSpec& spec, const LoadedField& loaded,
                          const std::vector<EigenFamily>& families, SourcePlacement placement, DataQuantity quantity) {
  const bool flow = loaded.vectors != nullptr;
  const bool several = families.size() > 1 && placement == SourcePlacement::along_trajectories;
  ColorScalar c = spec.color.value_or(flow                                    ? ColorScalar::speed
                                      : quantity == DataQuantity::diffusion ? ColorScalar::direction
                                      : several                             ? ColorScalar::family_eigenvalue
                                                                            : family_eigenvalue(families.front()));
  // Glyphs not on lines (or on one family's) show the first family's.
  if (c == ColorScalar::family_eigenvalue && !several) c = family_eigenvalue(families.front());
  const std::string& file = spec.data.file.path;
  if (flow && needs_tensors(c))
    throw DataError(file + ": glyphs.color_by = \"" + color_scalar_name(c) +
                    "\" needs tensors, and this file is read as a flow (vectors): colour by \"speed\" or "
                    "\"array:NAME\"");
  if (!flow && c == ColorScalar::speed)
    throw DataError((file.empty() ? std::string("the point load") : file) +
                    ": glyphs.color_by = \"speed\" needs a flow (vectors); this data holds tensors");
  if (c == ColorScalar::array && !loaded.color && loaded.sites.colors.empty())
    throw DataError("glyphs.color_by = \"array:NAME\" needs a data file that holds that array");
  if (c == ColorScalar::arc_length)
    throw DataError("glyphs.color_by = \"arc_length\" is for sources along a curve (glyphs.placement = \"curve\")");
  return c;
}

// Where the sources go: as the scene says, but data without volume has
// nothing to trace in or sample at seeds, so its glyphs stand at its
// points, said in a warning.
SourcePlacement resolved_placement(const GlyphPipelineSpec& spec, const LoadedField& loaded,
                                   std::vector<std::string>& warnings) {
  if (loaded.no_volume.empty() || spec.placement == SourcePlacement::at_data_points) return spec.placement;
  warnings.push_back(spec.data.file.path + ": " + loaded.no_volume + ": a glyph at each of its " +
                     std::to_string(loaded.sites.positions.size()) + " points instead (glyphs.placement = \"points\")");
  return SourcePlacement::at_data_points;
}

// The sites a glyph field draws from: every one, or with a region those
// whose tensor lies in it (each decomposed once, in parallel).
std::vector<std::size_t> sites_to_draw(const DataSites& sites, const RegionSpec& region) {
  std::vector<std::size_t> which;
  if (!region.restricts() || sites.tensors.empty()) {
    which.resize(sites.positions.size());
    for (std::size_t i = 0; i < which.size(); ++i) which[i] = i;
    return which;
  }
  std::vector<char> inside(sites.tensors.size());
  tbb::parallel_for(std::size_t{0}, inside.size(), [&](std::size_t i) {
    const Sym3& t = sites.tensors[i];
    if (!t.is_finite() || region.surely_below(t)) return;
    inside[i] = region.surely_above(t) ? region.in_mask(sites.positions[i])
                                       : region.holds(sites.positions[i], eigenvalues(t));
  });
  for (std::size_t i = 0; i < inside.size(); ++i)
    if (inside[i]) which.push_back(i);
  return which;
}

// A glyph at every stride-th of the sites `which`, from the value there (a
// tensor glyph or a streamball), coloured by the chosen scalar or the
// colour array there. Sites without a finite value (or colour) get none.
std::vector<GlyphSource> sources_at_sites(const DataSites& sites, const std::vector<std::size_t>& which,
                                          std::size_t stride, ColorScalar color) {
  // Made side by side (a decomposition each: 124,000 of them took 0.05 s
  // of one core on Teem's helix), then closed up in order.
  std::vector<GlyphSource> sources((which.size() + stride - 1) / stride);
  std::vector<char> made(sources.size());
  const bool flow = !sites.vectors.empty();
  tbb::parallel_for(std::size_t{0}, sources.size(), [&](std::size_t k) {
    const std::size_t i = which[k * stride];
    GlyphSource& source = sources[k];
    if (flow) {
      if (!sites.vectors[i].allFinite()) return;
      source = make_flow_source(sites.positions[i], sites.vectors[i], color);
    } else {
      if (i >= sites.tensors.size() || !sites.tensors[i].is_finite()) return;
      source = make_source(sites.positions[i], sites.tensors[i], color);
    }
    if (color == ColorScalar::array) {
      if (i >= sites.colors.size() || !std::isfinite(sites.colors[i])) return;
      source.scalar = sites.colors[i];
    }
    made[k] = 1;
  });
  std::size_t kept = 0;
  for (std::size_t k = 0; k < sources.size(); ++k)
    if (made[k]) sources[kept++] = sources[k];
  sources.resize(kept);
  return sources;
}

// Sources the scene itself gives (a curve, a list): no data set, sizes as
// given, the domain what they cover.
GlyphScene given_sources(const GlyphPipelineSpec& spec, double glyph_extent) {
  GlyphScene scene;
  const double before_sources = resident_bytes();
  if (spec.placement == SourcePlacement::curve) {
    scene.sources = curve_sources(spec.curve, glyph_extent);
    scene.trajectories.push_back(curve_points(spec.curve));
    scene.color = ColorScalar::arc_length;
  } else {
    scene.sources = read_source_list(spec.list_file, glyph_extent);
    scene.color = ColorScalar::array;
  }
  if (spec.color && *spec.color != scene.color)
    throw DataError(std::string("glyphs.color_by cannot be set with glyphs.placement = \"") +
                    (spec.placement == SourcePlacement::curve ? "curve\": sources are coloured along it"
                                                              : "list\": sources take the list's scalar column"));
  Box3 box{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
  for (const GlyphSource& s : scene.sources) {
    const Vec3 reach = Vec3::Constant(s.eigenvalues.maxCoeff());
    box = {box.lo.cwiseMin(s.centre - reach), box.hi.cwiseMax(s.centre + reach)};
  }
  if (scene.sources.empty()) box = {Vec3::Zero(), Vec3::Zero()};
  scene.memory_estimate = before_sources + double(scene.sources.size()) * kBytesPerSource;
  scene.domain = box;
  scene.values.mapping.mapping = RadiusMapping::constant;
  scene.values.mapping.floor = 0.0;
  return scene;
}

}  // namespace

namespace {

// Below this share of the body's typical stress, a family's line ends
// when several are traced: a tension line stops where the tension fades,
// and the compression lines take over there.
constexpr double kFamilyFloor = 0.05;

// The FA a diffusion volume's picture keeps above by default.
constexpr double kDiffusionRegion = 0.3;

// The eigenvalues at `points` (NaN where the data has none), in parallel.
std::vector<Vec3> eigenvalues_at(const std::vector<Vec3>& points, const TensorField& tensors) {
  std::vector<Vec3> values(points.size(), Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  tbb::parallel_for(std::size_t{0}, values.size(), [&](std::size_t i) {
    if (const std::optional<Sym3> t = tensors.sample(points[i])) values[i] = eigenvalues(*t);
  });
  return values;
}

// The families traced when the scene names none: major and minor
// (tension and compression lines) where the body holds both signs (λ1 > 0
// and λ3 < 0 somewhere, beyond 1 % of the largest |λ|); else the family
// of the one sign there, which carries the largest stresses: major for
// tension (and positive-definite data, as diffusion), minor for a body
// all in compression.
std::vector<EigenFamily> automatic_families(const std::vector<Vec3>& body_eigenvalues) {
  double most_tensile = 0.0, most_compressive = 0.0;
  for (const Vec3& l : body_eigenvalues)
    if (l.allFinite()) {
      most_tensile = std::max(most_tensile, l(0));
      most_compressive = std::min(most_compressive, l(2));
    }
  const double largest = std::max(most_tensile, -most_compressive);
  const bool tension = most_tensile > 0.01 * largest, compression = -most_compressive > 0.01 * largest;
  if (tension && compression) return {EigenFamily::major, EigenFamily::minor};
  return {compression ? EigenFamily::minor : EigenFamily::major};
}

// Where the traced families have no direction (every one of them
// degenerate) over a tenth of the body or more, nothing is drawn there:
// say how much, and what shows it. An isotropic background (a diffusion
// volume's fluid, a hydrostatic state) would otherwise fill the picture
// with spheres that hide the part that has a direction.
void warn_where_no_direction(GlyphScene& scene, const std::vector<Vec3>& body_eigenvalues) {
  const GlyphValues& values = scene.values;
  const double tolerance = values.trajectory.degeneracy_tolerance;
  std::size_t inside = 0, undirected = 0, isotropic = 0;
  for (const Vec3& l : body_eigenvalues) {
    if (!l.allFinite()) continue;
    ++inside;
    const bool none = std::none_of(values.families.begin(), values.families.end(), [&](EigenFamily f) {
      return eigenvector_defined(l, f, tolerance);
    });
    undirected += none;
    // λ1 = λ2 (no major direction) and λ2 = λ3 (no minor one): isotropic.
    isotropic += none && !eigenvector_defined(l, EigenFamily::major, tolerance) &&
                 !eigenvector_defined(l, EigenFamily::minor, tolerance);
  }
  if (inside == 0 || 10 * undirected < inside) return;
  std::ostringstream text;
  text << "no line is drawn over " << int(std::lround(100.0 * double(undirected) / double(inside)))
       << " % of the body, where "
       << (2 * isotropic >= undirected ? "the tensor is isotropic (λ1 = λ2 = λ3): no direction exists there"
                                       : "the traced family's eigenvalues are repeated: its direction is undefined")
       << "; glyphs.placement = \"points\" shows the sizes there";
  scene.warnings.push_back(text.str());
}

// Evenly spaced trajectories (even_seeding.h) through the body, for each
// family traced. Each family keeps its own lines apart: lines of two
// families cross at right angles by nature. With several families, each
// is as dense as its own |λ_k| against the body's typical stress and ends
// where that fades. No lone glyphs stand where a family has no direction
// (spheres in an isotropic background would hide the part of the body
// that has one), unless no family finds a line anywhere. The seeds taken
// are recorded in the values, in the frame the scene gives seeds in.
EvenTrajectories trace_evenly(GlyphScene& scene, const BodyLattice& body, const std::vector<Vec3>& body_eigenvalues,
                              const MagnitudeSampler& magnitude, const TensorField* tensors, const VectorField* flow) {
  GlyphValues& values = scene.values;
  EvenSeedingOptions options;
  options.separation = *values.seeds.separation;
  options.importance = *values.seeds.importance;
  if (scene.plane_axis) options.plane_normal = Vec3::Unit(*scene.plane_axis);
  const bool several = values.families.size() > 1;
  if (several) options.reference_magnitude = median_magnitude(body);
  options.lone_glyphs = false;
  const std::vector<Vec3> given = all_seeds(values.seeds, scene.domain);
  EvenTrajectories all;
  const auto trace_family = [&](EigenFamily family, bool per_family) {
    TrajectoryOptions trajectory = values.trajectory;
    trajectory.family = family;
    BodyLattice pool = body;
    MagnitudeSampler own = magnitude;
    if (per_family) {
      trajectory.family_magnitude = true;
      trajectory.min_family_value = kFamilyFloor * *options.reference_magnitude;
      own = [&, family](const Vec3& x) -> std::optional<double> {
        const std::optional<Sym3> t = tensors->sample(x);
        return t ? std::optional<double>(std::fabs(eigenvalues(*t)(int(family)))) : std::nullopt;
      };
      for (std::size_t i = 0; i < pool.points.size(); ++i) {
        const double m = std::fabs(body_eigenvalues[i](int(family)));
        pool.magnitudes[i] = std::isfinite(m) ? m : 0.0;
      }
    }
    const DirectionSampler direction = [&](const Vec3& x) {
      return flow ? flow_direction(*flow, x, trajectory) : eigen_direction(*tensors, x, trajectory);
    };
    EvenTrajectories lines = evenly_spaced_trajectories(direction, own, given, pool, trajectory, options);
    all.reference_magnitude = lines.reference_magnitude;
    all.reached_max_lines = all.reached_max_lines || lines.reached_max_lines;
    all.seeds.insert(all.seeds.end(), lines.seeds.begin(), lines.seeds.end());
    for (Trajectory& t : lines.trajectories) all.trajectories.push_back(std::move(t));
  };
  for (EigenFamily family : values.families) trace_family(family, several);
  if (all.trajectories.empty()) {
    // Isotropic everywhere: no family has a direction; lone glyphs show
    // the sizes at least.
    options.lone_glyphs = true;
    trace_family(values.families.front(), false);
  } else if (tensors) {
    warn_where_no_direction(scene, body_eigenvalues);
  }
  values.reference_magnitude = all.reference_magnitude;
  const Box3& b = scene.domain;
  values.seeds.points = all.seeds;
  values.seeds.grids.clear();
  if (values.seeds.frame == SeedFrame::bounds)
    for (Vec3& p : values.seeds.points) p = (p - b.lo).cwiseQuotient(b.size().cwiseMax(Vec3::Constant(1e-300)));
  if (all.reached_max_lines) {
    std::ostringstream text;
    text << "evenly spaced seeding stopped at " << options.max_lines << " trajectories (seeds.separation "
         << options.separation << "): parts of the body may have none; raise seeds.separation";
    scene.warnings.push_back(text.str());
  }
  return all;
}

}  // namespace

std::vector<double> color_range_values(const GlyphScene& scene) {
  std::vector<double> values;
  values.reserve(scene.sources.size() + scene.color_sample.size() + 2);
  for (const GlyphSource& s : scene.sources) values.push_back(s.scalar);
  // Without glyphs there is nothing to colour, and no range to widen.
  if (values.empty()) return values;
  values.insert(values.end(), scene.color_sample.begin(), scene.color_sample.end());
  if (scene.color_extremes) values.insert(values.end(), scene.color_extremes->begin(), scene.color_extremes->end());
  return values;
}

GlyphScene build_glyph_scene(const GlyphPipelineSpec& spec, double glyph_extent,
                             const std::function<void(const Box3& domain)>& with_domain, GlyphPlacing placing) {
  if (spec.placement == SourcePlacement::curve || spec.placement == SourcePlacement::list) {
    GlyphScene given = given_sources(spec, glyph_extent);
    if (with_domain) with_domain(given.domain);
    return given;
  }
  DataSpec data = spec.data;
  data.file.sites = spec.placement == SourcePlacement::at_data_points;
  if (data.kind == DataKind::point_load && !data.point_load.singular_radius)
    data.point_load.singular_radius = default_singular_radius(data.point_load.bounds);
  LoadedField loaded = make_field(data);
  const TensorField* tensors = loaded.field.get();
  const VectorField* flow = loaded.vectors.get();
  GlyphScene scene;
  scene.flow = flow != nullptr;
  scene.domain = flow ? flow->bounds() : tensors->bounds();
  if (with_domain) with_domain(scene.domain);
  scene.boundary = std::move(loaded.boundary);
  scene.plane_axis = loaded.plane_axis;
  scene.anatomical_frame = loaded.anatomical_frame;
  scene.warnings = std::move(loaded.warnings);
  scene.placement = resolved_placement(spec, loaded, scene.warnings);
  // Sampled only when the scene does not say.
  scene.quantity = data.quantity ? *data.quantity : loaded.quantity.value_or(DataQuantity::stress);
  // Diffusion: the fibres, where FA > 0.3, the usual threshold for white matter.
  RegionSpec region = spec.region;
  if (scene.quantity == DataQuantity::diffusion && !region.above && !flow) region.above = kDiffusionRegion;
  if (flow && spec.region.above)
    throw DataError(data.file.path + ": region.above keeps to where a measure of the tensor is large, and this "
                    "file is read as a flow (vectors)");
  // The mask array came with the data (data.file.mask_array); a mask file is read now.
  if (loaded.mask) region.mask_field = std::move(loaded.mask);
  else if (!region.mask.empty()) region.mask_field = load_mask(region.mask);
  // Evenly spaced seeding measures the body first: its separation sets
  // the step, the spacing and the glyph size.
  const bool even = scene.placement != SourcePlacement::at_data_points &&
                    spec.seeds.resolved_strategy() == SeedStrategy::even;
  const MagnitudeSampler magnitude = [&](const Vec3& x) -> std::optional<double> {
    // Outside the region is outside the body: seeds, separation and
    // the lines' density follow the region alone.
    if (flow) {
      const std::optional<Vec3> v = flow->sample(x);
      return v && region.in_mask(x) ? std::optional<double>(v->norm()) : std::nullopt;
    }
    const std::optional<Sym3> t = tensors->sample(x);
    if (!t || region.surely_below(*t)) return std::nullopt;
    const Vec3 l = eigenvalues(*t);
    return region.holds(x, l) ? std::optional<double>(l.cwiseAbs().maxCoeff()) : std::nullopt;
  };
  BodyLattice body;
  std::optional<double> separation;
  if (even) {
    body = lattice_in_body(scene.domain, magnitude, scene.plane_axis);
    separation = spec.seeds.separation.value_or(automatic_separation(body));
    if (!(*separation > 0.0)) separation = scene.domain.diagonal() / 10.0;  // no body: nothing will be found anyway
  }
  // Tensor lines need their eigenvalues over the body; a flow has one
  // direction, no families.
  // The eigenvalues at the body lattice's points, sampled once for the
  // choice of families and each family's own magnitudes.
  const std::vector<Vec3> body_eigenvalues = flow ? std::vector<Vec3>{} : eigenvalues_at(body.points, *tensors);
  if (flow && spec.trajectory.tensorlines)
    throw DataError(data.file.path + ": trajectories.method = \"tensorlines\" follows a tensor's major eigenvector, "
                    "and this file is read as a flow (vectors), whose streamlines need no method");
  // Tensorlines follow the major eigenvector only.
  std::vector<EigenFamily> families = {EigenFamily::major};
  if (!flow && !spec.trajectory.families.empty())
    families = spec.trajectory.families;
  // Diffusion draws its fibres, the major family: a minor eigenvector
  // runs across them.
  else if (!flow && even && scene.placement == SourcePlacement::along_trajectories && !spec.trajectory.tensorlines &&
           scene.quantity != DataQuantity::diffusion)
    families = automatic_families(body_eigenvalues);
  scene.color = resolve_color(spec, loaded, families, scene.placement, scene.quantity);
  if (tensors) {
    scene.color_extremes = data_color_extremes(*tensors, scene.color, families);
    if (scene.color_extremes) scene.color_sample = data_color_sample(*tensors, scene.color, families);
  }
  scene.values = resolve_lengths(spec, scene.domain, loaded, separation, families, scene.quantity);
  scene.values.region = region;
  if (region.above || spec.trajectory.stop_below) {
    scene.values.trajectory.measure = [measure = region.measure](const Vec3& l) { return color_scalar(l, measure); };
    scene.values.trajectory.min_measure = spec.trajectory.stop_below.value_or(region.above.value_or(0.0));
  }
  if (region.mask_field) scene.values.trajectory.inside = [region](const Vec3& x) { return region.in_mask(x); };
  if (data.kind == DataKind::point_load) scene.values.singular_radius = data.point_load.singular_radius;
  const GlyphValues& values = scene.values;
  // The source at a point of a line of `family`: a tensor glyph or a
  // streamball, coloured by the chosen scalar (each line's own eigenvalue
  // for family_eigenvalue) or by the colour array there.
  const ScalarField* color_array = scene.color == ColorScalar::array ? loaded.color.get() : nullptr;
  const auto maker = [&](EigenFamily family) -> SourceMaker {
    const ColorScalar color = scene.color == ColorScalar::family_eigenvalue ? family_eigenvalue(family) : scene.color;
    return [&, color, family](const Vec3& p) -> std::optional<GlyphSource> {
      std::optional<GlyphSource> source;
      if (flow) {
        if (const std::optional<Vec3> v = flow->sample(p)) source = make_flow_source(p, *v, color);
      } else if (const std::optional<Sym3> s = tensors->sample(p)) {
        source = make_source(p, *s, color);
      }
      if (source && color_array) {
        const std::optional<double> value = color_array->sample(p);
        if (!value) return std::nullopt;
        source->scalar = *value;
      }
      if (source) source->group = std::uint8_t(family);
      return source;
    };
  };
  const ColorScalar color = scene.color;
  const bool traced = scene.placement == SourcePlacement::along_trajectories ||
                      (even && scene.placement == SourcePlacement::at_seeds);
  if (placing == GlyphPlacing::on_body_lattice && traced) {
    // A source of each family at lattice points in the body: the
    // magnitudes and colours the lines would show, spread as evenly. A
    // few thousand give the mapping's percentile to a fraction of a
    // per cent; each costs a search of the mesh.
    if (!even) body = lattice_in_body(scene.domain, magnitude, scene.plane_axis);
    const std::size_t stride = body.points.size() / kLatticeGlyphs + 1;
    for (const EigenFamily family : values.families) {
      const SourceMaker make_here = maker(family);
      for (std::size_t i = 0; i < body.points.size(); i += stride)
        if (std::optional<GlyphSource> s = make_here(body.points[i])) scene.sources.push_back(std::move(*s));
    }
    std::vector<Vec3> eigenvalues;
    eigenvalues.reserve(scene.sources.size());
    for (const GlyphSource& s : scene.sources) eigenvalues.push_back(s.eigenvalues);
    const std::optional<double> gap = even ? std::optional<double>(line_gap(*separation)) : std::nullopt;
    scene.values.mapping = automatic_glyph_mapping(spec.size, eigenvalues, scene.domain, glyph_extent, gap,
                                                   even && scene.placement == SourcePlacement::along_trajectories);
    size_sources(scene.sources, scene.values.mapping);
    return scene;
  }
  std::vector<Vec3> seeds;
  if (even) {
    EvenTrajectories lines = trace_evenly(scene, body, body_eigenvalues, magnitude, tensors, flow);
    seeds = std::move(lines.seeds);
    scene.trajectories = std::move(lines.trajectories);
  } else if (scene.placement != SourcePlacement::at_data_points) {
    check_seed_and_trajectory_memory(values, scene.placement);
    seeds = all_seeds(values.seeds, scene.domain);
    // A seed outside the region has no line to start; nor a glyph.
    if (region.restricts())
      seeds.erase(std::remove_if(seeds.begin(), seeds.end(), [&](const Vec3& x) { return !magnitude(x); }),
                  seeds.end());
  }

  const SourceMaker make = maker(values.families.front());

  std::optional<double> gap;  // between glyphs at data points, or lines evenly spaced
  if (scene.placement == SourcePlacement::at_data_points) {
    const std::size_t sites = loaded.sites.positions.size();
    if (data.kind != DataKind::vtk_file)
      throw DataError("glyphs.placement = \"points\" needs a data file: the point load has no data points");
    // The stride thins the glyphs the region keeps; they stand as far
    // apart as the data's points at that stride.
    const std::vector<std::size_t> drawn = sites_to_draw(loaded.sites, region);
    const std::size_t kept = drawn.size();
    scene.values.stride = spec.stride.value_or(automatic_stride(kept));
    const auto thinned = [&](std::size_t n) {
      return (n + std::size_t(scene.values.stride) - 1) / std::size_t(scene.values.stride);
    };
    const std::size_t shown = thinned(kept);
    std::ostringstream what;
    what << "the glyphs (one at each of " << shown << " data points, glyphs.stride " << scene.values.stride << ")";
    scene.memory_estimate = resident_bytes() + double(shown) * kBytesPerSource;
    check_memory(scene.memory_estimate, what.str(), "raise glyphs.stride");
    scene.sources = sources_at_sites(loaded.sites, drawn, std::size_t(scene.values.stride), color);
    gap = site_gap(scene.domain, thinned(sites));
  } else if (scene.placement == SourcePlacement::at_seeds) {
    scene.trajectories.clear();  // even seeding's lines only chose the seeds
    scene.memory_estimate = resident_bytes() + double(seeds.size()) * kBytesPerSource;
    for (const Vec3& seed : seeds)
      if (std::optional<GlyphSource> s = make(seed)) scene.sources.push_back(std::move(*s));
    if (even) gap = line_gap(*separation);
  } else {
    // Each seed writes only its own slots, and the slots are concatenated in
    // seed order afterwards, so the result is independent of scheduling.
    if (!even) {
      // Every seed, once per family traced.
      const std::size_t n = seeds.size();
      scene.trajectories.resize(n * values.families.size());
      tbb::parallel_for(std::size_t{0}, scene.trajectories.size(), [&](std::size_t i) {
        TrajectoryOptions options = values.trajectory;
        options.family = values.families[i / n];
        scene.trajectories[i] = flow ? trace_streamline(*flow, seeds[i % n], options)
                                     : trace_trajectory(*tensors, seeds[i % n], options);
      });
    } else {
      gap = line_gap(*separation);
    }
    double count = 0.0;
    for (const Trajectory& t : scene.trajectories) count += source_count(t, values.spacing);
    std::ostringstream what;
    what << "the glyph sources (" << std::setprecision(count < 1e15 ? 15 : 3) << count << " of them along "
         << scene.trajectories.size()
         << " trajectories at glyphs.spacing " << values.spacing << ")";
    scene.memory_estimate = resident_bytes() + count * kBytesPerSource;
    check_memory(scene.memory_estimate, what.str(), "raise glyphs.spacing");
    std::vector<std::vector<GlyphSource>> per_line(scene.trajectories.size());
    tbb::parallel_for(std::size_t{0}, per_line.size(), [&](std::size_t i) {
      per_line[i] = place_sources(scene.trajectories[i], values.spacing, maker(scene.trajectories[i].family));
    });
    for (const std::vector<GlyphSource>& sources : per_line)
      scene.sources.insert(scene.sources.end(), sources.begin(), sources.end());
  }

  // The glyph size comes from the tensors (or speeds) the glyphs will show.
  std::vector<Vec3> eigenvalues;
  eigenvalues.reserve(scene.sources.size());
  for (const GlyphSource& s : scene.sources) eigenvalues.push_back(s.eigenvalues);
  const bool on_lines = even && scene.placement == SourcePlacement::along_trajectories;
  scene.values.mapping = automatic_glyph_mapping(spec.size, eigenvalues, scene.domain, glyph_extent, gap, on_lines);
  if (scene.values.beads) {
    // Placed again, now that their sizes are known; the mapping keeps the
    // statistics of the sources at `spacing`.
    const double spaced = double(scene.sources.size());
    scene.sources = beads_along(scene.trajectories, *scene.values.beads, scene.values.mapping,
                                glyph_extent * (flow ? spec.stretch : 1.0), values.spacing, maker);
    scene.memory_estimate += (double(scene.sources.size()) - spaced) * kBytesPerSource;
  }
  size_sources(scene.sources, scene.values.mapping);
  if (flow && spec.stretch != 1.0) stretch_sources(scene.sources, spec.stretch);
  if (scene.plane_axis)
    flatten_sources(scene.sources, Vec3::Unit(*scene.plane_axis),
                    spec.thickness ? std::optional<double>(0.5 * *spec.thickness) : std::nullopt);
  warn_about_the_result(scene, seeds.size());
  return scene;
}

}  // namespace hsb
