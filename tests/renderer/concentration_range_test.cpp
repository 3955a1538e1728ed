// A stress concentration is not an outlier: the automatic colour range
// spans the data's own values (field/glyph_pipeline.h: color_range_values),
// so a peak the lines do not reach (a hole's or a notch's edge) is coloured
// near its value, while a singular point's values (growing without bound
// towards a load point) stay beyond the range's fence and are marked.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "field/glyph_pipeline.h"
#include "renderer/image/colormap.h"

namespace hsb {
namespace {

ColorScale automatic_range(const GlyphScene& scene) {
  return auto_scale(colormap_named("coolwarm"), color_range_values(scene), true, false);
}

double data_max(const GlyphScene& scene) { return scene.color_extremes ? (*scene.color_extremes)[1] : 0.0; }

// The plate with a hole in millimetres and pascals, given alone: its lines
// pass beside the hole, whose edge carries the peak.
TEST(ConcentrationRange, AHolesPeakIsInsideTheRange) {
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::vtk_file;
  spec.data.file.path = std::string(HSB_SOURCE_DIR) + "/scenes/data/generated/plate_with_hole_mm_pa.vtu";
  const GlyphScene scene = build_glyph_scene(spec, 0.64);
  ASSERT_TRUE(scene.color_extremes);
  double glyphs_max = 0.0;
  for (const GlyphSource& s : scene.sources) glyphs_max = std::max(glyphs_max, s.scalar);
  // The lines alone fall short of the peak; the range does not.
  EXPECT_LT(glyphs_max, 0.95 * data_max(scene));
  EXPECT_GE(automatic_range(scene).hi, 0.999 * data_max(scene));  // the lines alone reached 0.87
}

// The point load sampled onto a grid: data of its own, and singular at the
// load. Its extreme values stay outliers, clipped and marked.
TEST(ConcentrationRange, ASingularPointIsStillClipped) {
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::point_load;
  spec.data.sample_grid = {33, 33, 33};
  const GlyphScene scene = build_glyph_scene(spec, 0.64);
  ASSERT_TRUE(scene.color_extremes);
  const ColorScale scale = automatic_range(scene);
  const double extreme = std::max(std::fabs((*scene.color_extremes)[0]), std::fabs((*scene.color_extremes)[1]));
  EXPECT_LT(std::max(std::fabs(scale.lo), std::fabs(scale.hi)), 0.5 * extreme);
  EXPECT_TRUE(scale.data_lo < scale.lo || scale.data_hi > scale.hi);  // the clipped end is marked
}

// Built by hand: glyph values near the bulk, the data's sample with a
// bounded peak of 3.3 times it, and one of a thousand times it.
TEST(ConcentrationRange, TheFenceTellsABoundedPeakFromASingularOne) {
  GlyphScene scene;
  for (int i = 0; i < 200; ++i) {
    GlyphSource s;
    s.scalar = 5.0 + 5.0 * (i % 10) / 9.0;  // 5 to 10
    scene.sources.push_back(s);
  }
  for (int i = 0; i < 5000; ++i) scene.color_sample.push_back(10.0 * (i % 100) / 99.0);  // 0 to 10
  scene.color_sample.push_back(33.0);
  scene.color_extremes = std::array<double, 2>{0.0, 33.0};
  EXPECT_GE(automatic_range(scene).hi, 33.0 * 0.999);
  scene.color_sample.back() = 1e4;
  scene.color_extremes = std::array<double, 2>{0.0, 1e4};
  const ColorScale singular = automatic_range(scene);
  EXPECT_LT(singular.hi, 100.0);
  EXPECT_EQ(singular.data_hi, 1e4);
  // Without glyphs nothing is coloured, and the data alone makes no range.
  scene.sources.clear();
  EXPECT_TRUE(color_range_values(scene).empty());
}

}  // namespace
}  // namespace hsb
