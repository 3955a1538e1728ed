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
  EXPECT_EQ(items[0].variant, "render.samples=1,glyphs.spacing=0.1,color.map=viridis");
  // An unreadable scene is one item: its error comes when it renders.
  std::ofstream(dir / "broken.toml") << "[glyphs\n";
  EXPECT_EQ(expand_batch({(dir / "broken.toml").string()}, {}).size(), 1u);
}

TEST(Batch, FilesGivenAsASeriesShareTheirScaleItemByItem) {
  const auto items = expand_batch({"p050.vtu", "p100.vtu", "p150.vtu"}, {"glyphs.mapping=sqrt,linear"}, true);
  ASSERT_EQ(items.size(), 6u);
  for (const BatchItem& item : items) {
    ASSERT_EQ(item.series.size(), 3u) << item.scene;
    // Each image shares with the same sweep value of every step, not with
    // the other values of its own step.
    for (const SeriesMember& member : item.series) EXPECT_EQ(member.overrides, item.overrides);
  }
  EXPECT_EQ(items[3].scene, "p100.vtu");
  EXPECT_EQ(items[3].series[0].scene, "p050.vtu");
  EXPECT_EQ(items[3].series[2].scene, "p150.vtu");
  EXPECT_EQ(items[3].overrides, (std::vector<std::string>{"glyphs.mapping=linear"}));
  // Without --series, files are unrelated pictures.
  for (const BatchItem& item : expand_batch({"p050.vtu", "p100.vtu"}, {})) EXPECT_TRUE(item.series.empty());
  // Steps that make different numbers of images cannot pair up.
  const auto dir = test_temp_dir("batch_test");
  const std::string swept = (dir / "swept_series.toml").string();
  std::ofstream(swept) << "[sweep]\n\"glyphs.spacing\" = [0.1, 0.2]\n";
  try {
    Batch({"p050.vtu", swept}, {}, true);
    ADD_FAILURE() << "steps of 1 and 2 images made one series";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--series: p050.vtu makes 1 images but " + swept + " makes 2"),
              std::string::npos)
        << e.what();
  }
}

TEST(Batch, ShardsHoldEveryItemExactlyOnce) {
  std::vector<std::string> scenes;
  for (int i = 0; i < 23; ++i) scenes.push_back("s" + std::to_string(i) + ".toml");
  const Batch batch(scenes, {"render.samples=1,2"});
  ASSERT_EQ(batch.size(), 46u);
  for (int n : {1, 2, 3, 7, 23, 40, 60}) {
    std::map<std::string, int> seen;
    std::size_t held = 0;
    for (int k = 1; k <= n; ++k) {
      const Shard shard{k, n};
      held += batch.shard_size(shard);
      for (std::size_t j = 0; j < batch.shard_size(shard); ++j) {
        const BatchItem item = batch.item(Batch::shard_position(shard, j));
        ++seen[item.scene + " " + item.variant];
      }
    }
    EXPECT_EQ(held, batch.size()) << n << " shards";
    EXPECT_EQ(seen.size(), batch.size()) << n << " shards";
    for (const auto& [name, count] : seen) EXPECT_EQ(count, 1) << name << " in " << n << " shards";
  }
  EXPECT_EQ(parse_shard("3/8").index, 3);
  EXPECT_EQ(parse_shard("3/8").count, 8);
  for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0", "1/2x", "-1/2"})
    EXPECT_THROW(parse_shard(bad), std::invalid_argument) << bad;
}

// Four keys of a hundred values are 10⁸ items: counted and taken by
// position at once, never listed (they once took 5 GB before --shard).
TEST(Batch, LargeSweepsAreCountedNotListed) {
  std::vector<std::string> overrides;
  std::string hundred;
  for (int v = 0; v < 100; ++v) hundred += (v ? "," : "") + std::to_string(v);
  for (const char* key : {"a.w", "a.x", "a.y", "a.z"}) overrides.push_back(std::string(key) + "=" + hundred);
  const Batch batch({"one.toml", "two.toml"}, overrides);
  EXPECT_EQ(batch.size(), 200000000u);
  const BatchItem item = batch.item(100000000u + 1234567u);  // the second scene's 1,234,567th
  EXPECT_EQ(item.scene, "two.toml");
  EXPECT_EQ(item.variant, "a.w=1,a.x=23,a.y=45,a.z=67");
  EXPECT_EQ(batch.shard_size({3, 1000}), 200000u);
  // More than a count can hold is refused, not wrapped around.
  std::vector<std::string> too_many(10, "k=" + hundred);
  for (std::size_t i = 0; i < too_many.size(); ++i) too_many[i][0] = char('a' + i);
  EXPECT_THROW(Batch({"x.toml"}, too_many), std::invalid_argument);
}

// An empty [sweep] list once indexed past its end (a crash); it is the
// scene's one item now, with an error at the list's line.
TEST(Batch, AnEmptySweepListIsALocatedError) {
  const auto dir = test_temp_dir("batch_test");
  const std::string scene = (dir / "empty_sweep.toml").string();
  std::ofstream(scene) << "[glyphs]\nscale = 0.2\n[sweep]\n\"glyphs.spacing\" = []\n";
  const Batch batch({scene}, {"render.samples=1,2"});
  ASSERT_EQ(batch.size(), 1u);
  const BatchItem item = batch.item(0);
  EXPECT_EQ(item.error, scene + ":4:20: sweep.glyphs.spacing lists no values; a sweep needs one or more");
}

// A bad value from the scene's [sweep] table is the table's, not a --set
// the user never typed.
TEST(Batch, ASweptValuesErrorNamesItsPlaceInTheScene) {
  const auto dir = test_temp_dir("batch_test");
  const std::string scene = (dir / "bad_sweep.toml").string();
  std::ofstream(scene) << "[sweep]\n\"glyphs.spacing\" = [0.1, -1]\n";
  const Batch batch({scene}, {"render.samples=1,2"});
  ASSERT_EQ(batch.size(), 4u);
  const BatchItem item = batch.item(1);  // render.samples=1, glyphs.spacing=-1
  EXPECT_EQ(item.variant, "render.samples=1,glyphs.spacing=-1");
  EXPECT_EQ(located_error(item, "--set glyphs.spacing=-1: glyphs.spacing must be > 0, got -1"),
            scene + ":2:26: in [sweep], glyphs.spacing must be > 0, got -1");
  // A --set sweep's value is the user's own --set.
  EXPECT_EQ(located_error(item, "--set render.samples=1: oops"), "--set render.samples=1: oops");
}

// A [sweep] table's strings and --set's bare words name an image alike:
// the table's 'magma' once named it color.map=_magma_ where --set named
// it color.map=magma.
TEST(Batch, ASweepTableAndASetSweepNameImagesAlike) {
  const auto dir = test_temp_dir("batch_test");
  const std::string swept = (dir / "swept_maps.toml").string(), plain = (dir / "plain_maps.toml").string();
  std::ofstream(swept) << "[sweep]\n\"color.map\" = [\"magma\", 'viridis']\n";
  std::ofstream(plain) << "[glyphs]\nscale = 0.2\n";
  const auto from_table = expand_batch({swept}, {});
  const auto from_set = expand_batch({plain}, {"color.map=magma,viridis"});
  const auto from_quoted_set = expand_batch({plain}, {"color.map=\"magma\",'viridis'"});
  ASSERT_EQ(from_table.size(), 2u);
  ASSERT_EQ(from_set.size(), 2u);
  ASSERT_EQ(from_quoted_set.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(from_table[i].variant, from_set[i].variant);
    EXPECT_EQ(from_quoted_set[i].variant, from_set[i].variant);
    EXPECT_EQ(file_for_variant("fig.png", from_table[i].variant), file_for_variant("fig.png", from_set[i].variant));
  }
  EXPECT_EQ(from_table[0].variant, "color.map=magma");
  EXPECT_EQ(file_for_variant("fig.png", from_table[1].variant), "fig_color.map=viridis.png");
  // What renders is still the TOML the table gave; only the name changed.
  EXPECT_EQ(from_table[0].overrides, (std::vector<std::string>{"color.map='magma'"}));
}

TEST(Batch, FileNamesSayTheSweptValues) {
  EXPECT_EQ(file_for_variant("fig09.png", ""), "fig09.png");
  EXPECT_EQ(file_for_variant("fig09.png", "glyphs.spacing=0.02"), "fig09_glyphs.spacing=0.02.png");
  EXPECT_EQ(file_for_variant("sub/x.exr", "camera.view=[1,0,0]"), "sub/x_camera.view=_1,0,0_.exr");
  EXPECT_EQ(file_for_variant("x.png", "color.map=\"magma\""), "x_color.map=_magma_.png");
}

}  // namespace
}  // namespace hsb
