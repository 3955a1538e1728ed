// Warnings for pictures that are certainly wrong: the user hears what to
// change instead of getting a flat colour.

#include <gtest/gtest.h>

#include "base/memory_budget.h"
#include "renderer/library/prepared_scene.h"

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

TEST(PictureWarnings, RaysThroughHundredsOfGlyphs) {
  // Dense spacing and large glyphs over a framed box: every ray crosses
  // most of them.
  const std::string crowded = seeds +
                              "[glyphs]\nspacing = 0.002\nmapping = \"constant\"\nscale = 2\n"
                              "[camera]\nframe = \"data\"\n";
  EXPECT_TRUE(mentions(warnings_for(crowded), "a ray crosses about"));
  EXPECT_FALSE(mentions(warnings_for(seeds), "a ray crosses about"));
}

// The message of the ResourceError (or SceneError) that preparing `scene` throws.
std::string refusal(const std::string& scene) {
  try {
    warnings_for(scene);
  } catch (const ResourceError& e) {
    return e.what();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "not refused";
}

TEST(ResourceLimits, ScenesLargerThanTheMachineAreRefusedBeforeAllocating) {
  // Each would take terabytes: refused at once, naming the estimate and the key.
  const std::string seeds_grid = refusal("[[seeds.grid]]\nn = 10000\nm = 10000\n");
  EXPECT_NE(seeds_grid.find("the trajectories (100000000 seeds"), std::string::npos) << seeds_grid;
  EXPECT_NE(seeds_grid.find("seeds.grid n and m"), std::string::npos) << seeds_grid;
  const std::string step = refusal(seeds + "[trajectories]\nstep = 4e-9\nmax_steps = 1000000000\n");
  EXPECT_NE(step.find("trajectories.step"), std::string::npos) << step;
  const std::string spacing = refusal(seeds + "[glyphs]\nspacing = 4e-9\n");
  EXPECT_NE(spacing.find("raise glyphs.spacing"), std::string::npos) << spacing;
  EXPECT_NE(spacing.find("would take about"), std::string::npos) << spacing;
  // Lengths no data set of this size can mean are refused against the
  // data's diagonal (D = 2√3 here), in its units, before any trajectory.
  for (const char* tiny : {"1e-20", "1e-300"}) {
    const std::string message = refusal(seeds + "[glyphs]\nspacing = " + tiny + "\n");
    EXPECT_NE(message.find("warned.toml:4:11: glyphs.spacing must be a length between 3.4641e-09 and 3.4641e+06 (1e-09 to "
                           "1e+06 times the data's diagonal D = 3.4641), got "),
              std::string::npos)
        << message;
  }
  const std::string huge = refusal(seeds + "[render]\nbox_radius = 1e15\n");
  EXPECT_NE(huge.find("render.box_radius must be a length between"), std::string::npos) << huge;
  const std::string at_seeds = refusal("[glyphs]\nplacement = \"seeds\"\n[[seeds.grid]]\nn = 10000\nm = 10000\n"
                                       "[[seeds.grid]]\nn = 10000\nm = 10000\n[[seeds.grid]]\nn = 10000\nm = 10000\n"
                                       "[[seeds.grid]]\nn = 10000\nm = 10000\n");
  EXPECT_NE(at_seeds.find("one at each of 400000000 seeds"), std::string::npos) << at_seeds;
  // A sampled grid of 10⁹ nodes was a bare std::bad_alloc.
  const std::string grid = refusal("[data]\nsample_grid = [1000, 1000, 1000]\n");
  EXPECT_NE(grid.find("the sampled grid (1000 × 1000 × 1000 nodes)"), std::string::npos) << grid;
  EXPECT_NE(grid.find("use a coarser data.sample_grid"), std::string::npos) << grid;
  // What fits is not refused.
  EXPECT_EQ(refusal(seeds), "not refused");
}

TEST(ResourceLimits, HumanSizes) {
  EXPECT_EQ(human_bytes(512), "512 bytes");
  EXPECT_EQ(human_bytes(2.345e9), "2.35 GB");
  EXPECT_EQ(human_bytes(7.69e12), "7.69 TB");
  EXPECT_GT(memory_budget_bytes(), std::size_t(100) << 20);
}

}  // namespace
}  // namespace hsb
