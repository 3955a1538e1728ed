// The batch: sweeps split at top-level commas only, every combination once,
// shards that together hold every item exactly once, and file names for
// each swept value.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "renderer/app/batch.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

TEST(Batch, SweepsSplitAtTopLevelCommasOnly) {
  EXPECT_EQ(split_sweep("0.02,0.05,0.1"), (std::vector<std::string>{"0.02", "0.05", "0.1"}));
  EXPECT_EQ(split_sweep("[1,2,3]"), (std::vector<std::string>{"[1,2,3]"}));
  EXPECT_EQ(split_sweep("[1,0,0],[0,1,0]"), (std::vector<std::string>{"[1,0,0]", "[0,1,0]"}));
  EXPECT_EQ(split_sweep("\"a,b\",'c,d'"), (std::vector<std::string>{"\"a,b\"", "'c,d'"}));
  EXPECT_EQ(split_sweep("sqrt"), (std::vector<std::string>{"sqrt"}));
}

TEST(Batch, EveryCombinationOfEverySweptKey) {
  const auto items = expand_batch({"a.toml", "b.vtu"},
                                  {"render.width=64", "glyphs.spacing=0.1,0.2,0.3", "glyphs.mapping=sqrt,linear"});
  ASSERT_EQ(items.size(), 12u);
  EXPECT_EQ(items[0].scene, "a.toml");
  EXPECT_EQ(items[0].overrides,
            (std::vector<std::string>{"render.width=64", "glyphs.spacing=0.1", "glyphs.mapping=sqrt"}));
  EXPECT_EQ(items[0].variant, "glyphs.spacing=0.1,glyphs.mapping=sqrt");
  EXPECT_EQ(items[1].variant, "glyphs.spacing=0.1,glyphs.mapping=linear");  // the last key fastest
  EXPECT_EQ(items[5].variant, "glyphs.spacing=0.3,glyphs.mapping=linear");
  EXPECT_EQ(items[6].scene, "b.vtu");
  // Without sweeps: one item a scene, no variant.
  const auto plain = expand_batch({"a.toml"}, {"render.width=64", "camera.position=[1,2,3]"});
  ASSERT_EQ(plain.size(), 1u);
  EXPECT_EQ(plain[0].variant, "");
  EXPECT_EQ(plain[0].overrides.size(), 2u);
}

TEST(Batch, ASceneSweepTableAddsItsKeys) {
  const auto dir = test_temp_dir("batch_test");
  const std::string scene = (dir / "swept.toml").string();
  std::ofstream(scene) << "[glyphs]\nscale = 0.2\n[sweep]\n\"glyphs.spacing\" = [0.1, 0.2]\n"
                          "[sweep.color]\nmap = [\"viridis\", \"magma\"]\n";
  const auto items = expand_batch({scene}, {"render.samples=1,2"});
  ASSERT_EQ(items.size(), 8u);
  std::map<std::string, int> seen;
  for (const BatchItem& item : items) ++seen[item.variant];
  EXPECT_EQ(seen.size(), 8u);  // each combination once
  EXPECT_EQ(items[0].variant, "render.samples=1,glyphs.spacing=0.1,color.map='viridis'");
  // An unreadable scene is one item: its error comes when it renders.
  std::ofstream(dir / "broken.toml") << "[glyphs\n";
  EXPECT_EQ(expand_batch({(dir / "broken.toml").string()}, {}).size(), 1u);
}

TEST(Batch, ShardsHoldEveryItemExactlyOnce) {
  std::vector<BatchItem> items;
  for (int i = 0; i < 23; ++i) items.push_back({"s" + std::to_string(i) + ".toml", {}, ""});
  for (int n : {1, 2, 3, 7, 23, 40}) {
    std::map<std::string, int> seen;
    for (int k = 1; k <= n; ++k)
      for (const BatchItem& item : shard_items(items, {k, n})) ++seen[item.scene];
    EXPECT_EQ(seen.size(), items.size()) << n << " shards";
    for (const auto& [scene, count] : seen) EXPECT_EQ(count, 1) << scene << " in " << n << " shards";
  }
  EXPECT_EQ(parse_shard("3/8").index, 3);
  EXPECT_EQ(parse_shard("3/8").count, 8);
  for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0", "1/2x", "-1/2"})
    EXPECT_THROW(parse_shard(bad), std::invalid_argument) << bad;
}

TEST(Batch, FileNamesSayTheSweptValues) {
  EXPECT_EQ(file_for_variant("fig09.png", ""), "fig09.png");
  EXPECT_EQ(file_for_variant("fig09.png", "glyphs.spacing=0.02"), "fig09_glyphs.spacing=0.02.png");
  EXPECT_EQ(file_for_variant("sub/x.exr", "camera.view=[1,0,0]"), "sub/x_camera.view=_1,0,0_.exr");
  EXPECT_EQ(file_for_variant("x.png", "color.map=\"magma\""), "x_color.map=_magma_.png");
}

}  // namespace
}  // namespace hsb
