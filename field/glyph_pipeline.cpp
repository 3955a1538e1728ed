#include "field/glyph_pipeline.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "field/seeding.h"
#include "field/uniform_grid.h"

namespace hsb {

LoadedField make_field(const DataSpec& spec) {
  LoadedField loaded;
  if (spec.kind == DataKind::vtk_file) {
    VtkData data = load_vtk_data(spec.file);
    loaded.field = std::move(data.field);
    loaded.boundary = std::move(data.boundary);
    loaded.warnings = std::move(data.warnings);
  } else {
    loaded.field = std::make_unique<PointLoadField>(spec.point_load);
  }
  const auto& dims = spec.sample_grid;
  if (std::all_of(dims.begin(), dims.end(), [](int d) { return d >= 2; }))
    loaded.field = std::make_unique<UniformGridField>(UniformGridField::sampled_from(*loaded.field, dims));
  return loaded;
}

namespace {

// The default seeding: 5×5 on the middle cross-section across the longest
// axis of the bounds, in bounds fractions.
SeedGridSpec default_seed_grid(const Box3& bounds) {
  Eigen::Index longest = 0;
  bounds.size().maxCoeff(&longest);
  const Eigen::Index u = (longest + 1) % 3, v = (longest + 2) % 3;
  SeedGridSpec grid;
  grid.corner = Vec3::Zero();
  grid.corner[longest] = 0.5;
  grid.edge_u = Vec3::Unit(u);
  grid.edge_v = Vec3::Unit(v);
  grid.n = grid.m = 5;
  return grid;
}

std::vector<Vec3> all_seeds(const GlyphPipelineSpec& spec, const Box3& bounds) {
  std::vector<Vec3> seeds = spec.seed_points;
  std::vector<SeedGridSpec> grids = spec.seed_grids;
  SeedFrame frame = spec.seed_frame;
  if (seeds.empty() && grids.empty()) {
    grids.push_back(default_seed_grid(bounds));
    frame = SeedFrame::bounds;
  }
  for (const SeedGridSpec& g : grids) {
    const std::vector<Vec3> grid = grid_seeds(g.corner, g.edge_u, g.edge_v, g.n, g.m);
    seeds.insert(seeds.end(), grid.begin(), grid.end());
  }
  if (frame == SeedFrame::bounds) {
    for (Vec3& s : seeds) s = bounds.lo + bounds.size().cwiseProduct(s);
  }
  return seeds;
}

// An empty picture deserves a reason.
void warn_if_empty(GlyphScene& scene, std::size_t seeds) {
  if (scene.sources.empty())
    scene.warnings.push_back("no glyph sources: none of the " + std::to_string(seeds) +
                             " seeds lies inside the data set where it can be sampled");
}

}  // namespace

GlyphScene build_glyph_scene(const GlyphPipelineSpec& spec_in) {
  LoadedField loaded = make_field(spec_in.data);
  const TensorField* field = loaded.field.get();
  GlyphScene scene;
  scene.domain = field->bounds();
  const std::vector<Vec3> seeds = all_seeds(spec_in, scene.domain);
  scene.boundary = std::move(loaded.boundary);
  scene.warnings = std::move(loaded.warnings);

  // Resolve the automatic lengths against the data set's size.
  GlyphPipelineSpec spec = spec_in;
  const double diagonal = scene.domain.diagonal();
  if (spec.trajectory.step <= 0.0) spec.trajectory.step = diagonal / 400.0;
  if (spec.trajectory.max_length <= 0.0) spec.trajectory.max_length = 2.0 * diagonal;
  if (spec.spacing <= 0.0) spec.spacing = diagonal / 40.0;

  if (spec.placement == SourcePlacement::at_seeds) {
    for (const Vec3& seed : seeds) {
      if (const std::optional<Sym3> s = field->sample(seed))
        scene.sources.push_back(make_source(seed, *s, spec.mapping, spec.color));
    }
    warn_if_empty(scene, seeds.size());
    return scene;
  }

  // Each seed writes only its own slots, and the slots are concatenated in
  // seed order afterwards, so the result is independent of scheduling.
  scene.trajectories.resize(seeds.size());
  std::vector<std::vector<GlyphSource>> per_seed(seeds.size());
  tbb::parallel_for(std::size_t{0}, seeds.size(), [&](std::size_t i) {
    scene.trajectories[i] = trace_trajectory(*field, seeds[i], spec.trajectory);
    per_seed[i] = place_sources(*field, scene.trajectories[i], spec.spacing, spec.mapping,
                                spec.color);
  });
  for (const std::vector<GlyphSource>& sources : per_seed)
    scene.sources.insert(scene.sources.end(), sources.begin(), sources.end());
  warn_if_empty(scene, seeds.size());
  return scene;
}

}  // namespace hsb
