#pragma once
// The whole field side of a scene in one call: data set → seeds →
// trajectories → sources. The renderer fills a GlyphPipelineSpec from a scene
// file and receives sources; it never touches a data set itself.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "field/glyph_sources.h"
#include "field/point_load.h"
#include "field/trajectory.h"
#include "field/triangle_mesh.h"
#include "field/vtk_data.h"

namespace hsb {

enum class DataKind { point_load, vtk_file };

struct DataSpec {
  DataKind kind = DataKind::point_load;
  PointLoadSpec point_load;
  VtkFileSpec file;
  // When all three are ≥ 2, the data set is sampled onto a grid of these
  // dimensions spanning its bounds, and everything downstream reads the grid.
  std::array<int, 3> sample_grid{0, 0, 0};
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

enum class SourcePlacement {
  along_trajectories,  // hyperstreamballs: sources spaced along tensor lines
  at_seeds,            // one glyph per seed point: classic ellipsoid glyphs
};

// Lengths given as 0 are "automatic": fractions of the data set's diagonal D,
// known only once the data set is read (trajectory.step = D/400,
// trajectory.max_length = 2 D, spacing = D/40).
struct GlyphPipelineSpec {
  DataSpec data;
  // With neither points nor grids, a 5×5 grid on the cross-section through
  // the middle of the bounding box, across its longest axis: trajectories
  // along the body of a bar, beam or rail.
  std::vector<Vec3> seed_points;
  std::vector<SeedGridSpec> seed_grids;
  SeedFrame seed_frame = SeedFrame::world;
  TrajectoryOptions trajectory;
  SourcePlacement placement = SourcePlacement::along_trajectories;
  double spacing = 0.0;
  GlyphMapping mapping;
  ColorScalar color = ColorScalar::lambda3;
};

struct GlyphScene {
  Box3 domain;
  std::vector<Trajectory> trajectories;
  std::vector<GlyphSource> sources;
  std::optional<TriangleMesh> boundary;  // a mesh's outer surface (none for analytic data)
  std::vector<std::string> warnings;     // about the data, for the user
};

struct LoadedField {
  std::unique_ptr<TensorField> field;
  std::optional<TriangleMesh> boundary;
  std::vector<std::string> warnings;
};

// Builds (or reads) the data set described by `spec`. Throws DataError for
// unusable data files.
LoadedField make_field(const DataSpec& spec);

// Runs the pipeline. Trajectories are traced in parallel-safe order and the
// result does not depend on thread count.
GlyphScene build_glyph_scene(const GlyphPipelineSpec& spec);

}  // namespace hsb
