// Warnings for pictures that are certainly wrong: the user hears what to
// change instead of getting a flat colour.

#include <gtest/gtest.h>

#include "renderer/app/prepared_scene.h"

namespace hsb {
namespace {

std::vector<std::string> warnings_for(const std::string& scene) {
  const ColorManagement color("", "");
  return prepare_scene(load_scene_text(scene, "warned.toml", ""), color)->warnings;
}

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  for (const std::string& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

const std::string seeds = "[seeds]\npoints = [[0, 0, 0.5], [0.3, 0.2, 0.4]]\n";

TEST(PictureWarnings, GlyphsLargerThanTheDataSet) {
  // Linear radii in units of the load, scale 1: glyphs hundreds of times
  // the body (a scale meant for other units).
  const auto w = warnings_for(seeds + "[glyphs]\nmapping = \"linear\"\nscale = 100\nceiling = inf\n");
  EXPECT_TRUE(mentions(w, "larger than the whole data set"));
  EXPECT_TRUE(mentions(w, "glyphs.scale"));
  EXPECT_FALSE(mentions(warnings_for(seeds), "larger than the whole data set"));
}

TEST(PictureWarnings, CameraInsideTheSurface) {
  const auto w = warnings_for(seeds + "[camera]\nposition = [0, 0, 0.5]\nlook_at = [1, 0, 0.5]\n");
  EXPECT_TRUE(mentions(w, "camera is inside the surface"));
  EXPECT_FALSE(mentions(warnings_for(seeds), "camera is inside"));
}

}  // namespace
}  // namespace hsb
