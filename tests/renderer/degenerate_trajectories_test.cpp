// Trajectories with nothing to them: a seed outside the data, a seed on a
// degenerate (zero) tensor, a length shorter than a step. render, export
// and info go through; the user hears why the picture is nearly empty, and
// no file is left half-written.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "renderer/app/export_job.h"
#include "renderer/app/render_job.h"
#include "renderer/library/pinned_scene.h"
#include "renderer/library/prepared_scene.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

const std::string zero_stress = std::string(HSB_SOURCE_DIR) + "/scenes/data/generated/zero_stress_regions.vti";

// Seeds in the corners of the cube (zero stress: every eigenvalue equal)
// and one outside it.
const std::string degenerate_scene = "[data]\nfile = \"" + zero_stress + "\"\n[seeds]\nframe = \"bounds\"\n"
                                     "points = [[0.05, 0.05, 0.05], [0.95, 0.95, 0.95], [3, 3, 3]]\n"
                                     "[render]\nwidth = 48\nheight = 48\n";

std::vector<std::string> leftovers(const fs::path& dir) {
  std::vector<std::string> found;
  if (!fs::exists(dir)) return found;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().find(".partial") != std::string::npos) found.push_back(entry.path());
  return found;
}

TEST(DegenerateTrajectories, SeedsOnZeroStressAndOutsideTheData) {
  const fs::path dir = test_temp_dir("degenerate_test", true);
  const fs::path scene = dir / "degenerate.toml";
  std::ofstream(scene) << degenerate_scene;

  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> p = prepare_scene(load_scene(scene.string()), color);
  ASSERT_EQ(p->glyphs.trajectories.size(), 3u);
  for (const Trajectory& t : p->glyphs.trajectories) EXPECT_EQ(t.points.size(), 1u);
  // A glyph at each seed inside the data (a sphere: the tensor is zero).
  EXPECT_EQ(p->glyphs.sources.size(), 2u);
  bool told = false;
  for (const std::string& w : p->warnings) told |= w.find("no trajectory is longer than one step") != std::string::npos;
  EXPECT_TRUE(told);

  const RenderSummary rendered = run_render_job({scene.string(), {}, (dir / "out").string()});
  EXPECT_TRUE(fs::exists(rendered.image_path));
  const std::vector<std::string> exported = run_export_job({scene.string(), {}, (dir / "out").string()});
  for (const std::string& f : exported) EXPECT_GT(fs::file_size(f), 0u) << f;
  EXPECT_NE(pinned_scene_toml(*p).find("[seeds]"), std::string::npos);
  EXPECT_TRUE(leftovers(dir / "out").empty()) << leftovers(dir / "out").front();
}

TEST(DegenerateTrajectories, ShorterThanOneStep) {
  const std::string scene = "[seeds]\npoints = [[0, 0, 0.5], [0.2, 0.1, 0.3]]\n[trajectories]\nmax_length = 1e-6\n";
  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> p = prepare_scene(load_scene_text(scene, "short.toml", ""), color);
  for (const Trajectory& t : p->glyphs.trajectories) EXPECT_LE(t.length(), 2e-6);
  EXPECT_EQ(p->glyphs.sources.size(), 2u);
  bool told = false;
  for (const std::string& w : p->warnings) told |= w.find("most stop at trajectories.max_length") != std::string::npos;
  EXPECT_TRUE(told);
}

TEST(DegenerateTrajectories, NoSeedInsideTheData) {
  const std::string scene = "[seeds]\npoints = [[5, 5, 5]]\n";
  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> p = prepare_scene(load_scene_text(scene, "outside.toml", ""), color);
  EXPECT_TRUE(p->glyphs.sources.empty());
  ASSERT_FALSE(p->warnings.empty());
  EXPECT_NE(p->warnings[0].find("no glyph sources"), std::string::npos);
  // The camera still frames something: the data's bounds.
  EXPECT_FALSE(p->glyphs.domain.contains(p->camera.position));
}

}  // namespace
}  // namespace hsb
