// Glyphs sampled on the body's lattice (GlyphPlacing::on_body_lattice),
// which a time series reads from every step in place of tracing it:
// they must give the scale the traced glyphs give, and colours from the
// same data, or a series' shared scale would be another picture's.

#include <gtest/gtest.h>

#include <string>

#include "field/glyph_pipeline.h"

namespace hsb {
namespace {

constexpr double kExtent = 0.64;  // the renderer's default glyph extent

GlyphPipelineSpec file_scene(const std::string& name) {
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::vtk_file;
  spec.data.file.path = std::string(HSB_SOURCE_DIR) + "/scenes/data/" + name;
  return spec;
}

GlyphPipelineSpec point_load_scene() {
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::point_load;
  spec.data.point_load.bounds = Box3{Vec3(-1, -1, -1), Vec3(1, 1, 0)};
  return spec;
}

struct Case {
  const char* name;
  GlyphPipelineSpec spec;
};

std::vector<Case> cases() {
  GlyphPipelineSpec hyperstreamsurfaces = file_scene("cylinder_stress_coarse.vtu");
  hyperstreamsurfaces.trajectory.families = {EigenFamily::major, EigenFamily::medium, EigenFamily::minor};
  return {{"plate with a hole, even seeding", file_scene("formats/kirsch_plate_series_2.vtu")},
          {"thick cylinder", file_scene("cylinder_stress_coarse.vtu")},
          {"thick cylinder, three families", hyperstreamsurfaces}};
}

TEST(LatticeGlyphs, GiveTheTracedGlyphsScale) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const GlyphScene traced = build_glyph_scene(c.spec, kExtent);
    const GlyphScene sampled = build_glyph_scene(c.spec, kExtent, {}, GlyphPlacing::on_body_lattice);
    ASSERT_FALSE(traced.sources.empty());
    ASSERT_FALSE(sampled.sources.empty());
    EXPECT_TRUE(sampled.trajectories.empty()) << "nothing is traced";
    // The same reference glyph within a fifth: the 90th percentile of
    // lines' glyphs and of evenly spread ones differ by where lines go.
    // (Not so near a singular point load, whose lines crowd at the load:
    // there the lattice's scale is twice the lines'. A series uses it
    // only to find its largest step, which it then traces.)
    EXPECT_NEAR(sampled.values.mapping.scale / traced.values.mapping.scale, 1.0, 0.2);
    // What does not depend on the glyphs is the traced scene's.
    EXPECT_EQ(sampled.color, traced.color);
    EXPECT_EQ(sampled.values.families, traced.values.families);
    EXPECT_EQ(sampled.color_extremes, traced.color_extremes);
    EXPECT_EQ(sampled.color_sample, traced.color_sample);
  }
}

TEST(LatticeGlyphs, OrderStepsAsTracingDoes) {
  // A load that doubles halves the automatic scale at a linear mapping.
  GlyphPipelineSpec spec = point_load_scene();
  spec.size.mapping = RadiusMapping::linear;
  const GlyphScene one = build_glyph_scene(spec, kExtent, {}, GlyphPlacing::on_body_lattice);
  const GlyphScene traced_one = build_glyph_scene(spec, kExtent);
  spec.data.point_load.load *= 2.0;
  const GlyphScene two = build_glyph_scene(spec, kExtent, {}, GlyphPlacing::on_body_lattice);
  EXPECT_NEAR(two.values.mapping.scale / one.values.mapping.scale, 0.5, 1e-9);
  EXPECT_NEAR(two.values.mapping.scale / one.values.mapping.scale,
              build_glyph_scene(spec, kExtent).values.mapping.scale / traced_one.values.mapping.scale, 1e-9);
}

TEST(LatticeGlyphs, PlacementsThatTraceNothingAreAsSpecified) {
  GlyphPipelineSpec spec = file_scene("cylinder_stress_coarse.vtu");
  spec.placement = SourcePlacement::at_data_points;
  const GlyphScene points = build_glyph_scene(spec, kExtent);
  const GlyphScene sampled = build_glyph_scene(spec, kExtent, {}, GlyphPlacing::on_body_lattice);
  ASSERT_EQ(sampled.sources.size(), points.sources.size());
  EXPECT_DOUBLE_EQ(sampled.values.mapping.scale, points.values.mapping.scale);
}

}  // namespace
}  // namespace hsb
