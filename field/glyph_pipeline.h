#pragma once
// The whole field side of a scene in one call: data set → seeds →
// trajectories → sources. The renderer fills a GlyphPipelineSpec from a scene
// file and receives sources; it never touches a data set itself.

#include <array>
#include <memory>
#include <vector>

#include "field/glyph_sources.h"
#include "field/point_load.h"
#include "field/trajectory.h"

namespace hsb {

struct DataSpec {
  PointLoadSpec point_load;
  // When all three are ≥ 2, the analytic field is sampled onto a grid of
  // these dimensions and everything downstream reads the grid instead.
  std::array<int, 3> sample_grid{0, 0, 0};
};

struct SeedGridSpec {
  Vec3 corner = Vec3::Zero();
  Vec3 edge_u = Vec3::UnitX();
  Vec3 edge_v = Vec3::UnitY();
  int n = 3;
  int m = 3;
};

enum class SourcePlacement {
  along_trajectories,  // hyperstreamballs: sources spaced along tensor lines
  at_seeds,            // one glyph per seed point: classic ellipsoid glyphs
};

struct GlyphPipelineSpec {
  DataSpec data;
  std::vector<Vec3> seed_points;
  std::vector<SeedGridSpec> seed_grids;
  TrajectoryOptions trajectory;
  SourcePlacement placement = SourcePlacement::along_trajectories;
  double spacing = 0.1;
  GlyphMapping mapping;
  ColorScalar color = ColorScalar::lambda3;
};

struct GlyphScene {
  Box3 domain;
  std::vector<Trajectory> trajectories;
  std::vector<GlyphSource> sources;
};

// Builds the data set described by `spec.data`.
std::unique_ptr<TensorField> make_field(const DataSpec& spec);

// Runs the pipeline. Trajectories are traced in parallel-safe order and the
// result does not depend on thread count.
GlyphScene build_glyph_scene(const GlyphPipelineSpec& spec);

}  // namespace hsb
