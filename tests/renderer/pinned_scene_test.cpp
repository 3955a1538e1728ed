// hsb info's pinned scene: every automatic value written out, so that the
// printed scene renders the same picture and has nothing automatic left.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "renderer/library/pinned_scene.h"
#include "renderer/library/prepared_scene.h"

namespace hsb {
namespace {

std::unique_ptr<PreparedScene> prepare(SceneSpec spec) {
  const ColorManagement color("", "");
  return prepare_scene(std::move(spec), color);
}

void expect_same_picture(const PreparedScene& a, const PreparedScene& b) {
  const double tolerance = 1e-12 * a.glyphs.domain.diagonal();
  EXPECT_LT((a.camera.position - b.camera.position).norm(), tolerance);
  EXPECT_LT((a.camera.look_at - b.camera.look_at).norm(), tolerance);
  EXPECT_EQ(a.camera.up, b.camera.up);
  EXPECT_EQ(a.camera.projection, b.camera.projection);
  EXPECT_DOUBLE_EQ(a.glyphs.values.spacing, b.glyphs.values.spacing);
  EXPECT_DOUBLE_EQ(a.glyphs.values.trajectory.step, b.glyphs.values.trajectory.step);
  EXPECT_DOUBLE_EQ(a.glyphs.values.mapping.scale, b.glyphs.values.mapping.scale);
  EXPECT_DOUBLE_EQ(a.glyphs.values.mapping.floor, b.glyphs.values.mapping.floor);
  EXPECT_DOUBLE_EQ(a.glyphs.values.mapping.ceiling, b.glyphs.values.mapping.ceiling);
  EXPECT_DOUBLE_EQ(a.scale.lo, b.scale.lo);
  EXPECT_DOUBLE_EQ(a.scale.hi, b.scale.hi);
  EXPECT_EQ(a.context.box.has_value(), b.context.box.has_value());
  EXPECT_EQ(a.context.shell != nullptr, b.context.shell != nullptr);
  EXPECT_EQ(a.output.file, b.output.file);
  ASSERT_EQ(a.field.sources.size(), b.field.sources.size());
  for (std::size_t i = 0; i < a.field.sources.size(); ++i) {
    EXPECT_EQ(a.field.sources[i].w, b.field.sources[i].w);
    EXPECT_EQ(a.field.sources[i].centre, b.field.sources[i].centre);
  }
}

void round_trip(const SceneSpec& spec) {
  const std::unique_ptr<PreparedScene> original = prepare(spec);
  ASSERT_FALSE(automatic_keys(*original).empty());
  const std::string pinned = pinned_scene_toml(*original);
  SCOPED_TRACE(pinned);
  const std::unique_ptr<PreparedScene> again =
      prepare(load_scene_text(pinned, spec.path, spec.base_dir));
  expect_same_picture(*original, *again);
  const std::vector<std::string> left = automatic_keys(*again);
  EXPECT_TRUE(left.empty()) << "still automatic: " << left.front();
}

TEST(PinnedScene, AnAnalyticSceneRoundTrips) {
  round_trip(load_scene_text("[[seeds.grid]]\ncorner = [-0.4, -0.4, 0.7]\nedge_u = [0.8, 0, 0]\n"
                             "edge_v = [0, 0.8, 0]\nn = 2\nm = 2\n[trajectories]\nfamily = \"minor\"\n",
                             "analytic.toml", ""));
}

TEST(PinnedScene, ADataFileRoundTrips) {
  round_trip(scene_for_data_file(std::string(HSB_SOURCE_DIR) + "/scenes/data/cylinder_stress_coarse.vtu",
                                 {"render.width=300", "render.height=200"}));
}

// `hsb info FILE > dir/FILE.toml`, the file named relative to where hsb
// ran: the pinned scene, read from another folder, finds the same data
// and makes the same picture (evenly spaced seeds, the body's shape).
TEST(PinnedScene, ADataFilePinnedElsewhereFindsItsData) {
  const std::filesystem::path here = std::filesystem::current_path();
  std::filesystem::current_path(std::string(HSB_SOURCE_DIR) + "/scenes/data");
  const std::unique_ptr<PreparedScene> original = prepare(scene_for_data_file("cylinder_stress_coarse.vtu", {}));
  const std::string pinned = pinned_scene_toml(*original);
  std::filesystem::current_path(here);
  SCOPED_TRACE(pinned);
  const std::unique_ptr<PreparedScene> again = prepare(load_scene_text(pinned, "/tmp/elsewhere/c.toml", "/tmp/elsewhere"));
  expect_same_picture(*original, *again);
  EXPECT_EQ(original->render.width, again->render.width);
  EXPECT_EQ(original->render.height, again->render.height);
}

TEST(PinnedScene, AnOrthographicViewRoundTrips) {
  round_trip(load_scene_text("[camera]\nview = \"top\"\nprojection = \"orthographic\"\n[glyphs]\n"
                             "mapping = \"normalized\"\n",
                             "ortho.toml", ""));
}

}  // namespace
}  // namespace hsb
