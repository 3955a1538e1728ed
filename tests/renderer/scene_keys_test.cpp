// The scene schema: every default it states is a value its own key
// accepts, the reader reads no key it does not list, and a near miss of a
// key is named.

#include <gtest/gtest.h>

#include "renderer/scene/scene_keys.h"
#include "renderer/scene/scene_spec.h"

namespace hsb {
namespace {

const std::string data_file = std::string(HSB_SOURCE_DIR) + "/scenes/data/cylinder_stress_coarse.vtu";

// A scene in which `key` applies, as TOML text.
std::string scene_for(const std::string& key) {
  if (key == "glyphs.curve.from" || key == "glyphs.curve.to")
    return "[glyphs]\nplacement = \"curve\"\n[glyphs.curve]\nkind = \"line\"\n";
  if (key.rfind("glyphs.curve.", 0) == 0) return "[glyphs]\nplacement = \"curve\"\n";
  if (key == "glyphs.sharpness") return "[glyphs]\nshape = \"superquadric\"\n";
  if (key == "data.field" || key == "data.association" || key == "data.cell_tensors" || key == "data.components")
    return "[data]\nfile = \"" + data_file + "\"\n";
  return "";
}

TEST(SceneKeys, EveryDefaultIsAValueItsKeyAccepts) {
  int tried = 0;
  for (const KeySchema& key : scene_keys()) {
    if (key.default_kind != KeyDefault::value) {
      EXPECT_FALSE(key.rule.empty()) << key.path << ": a key without a default says what happens instead";
      continue;
    }
    ASSERT_NE(default_node(key), nullptr) << key.path << ": its default " << key.fallback << " is not TOML";
    if (key.path.rfind("seeds.grid.", 0) == 0 || key.path.rfind("panel.", 0) == 0) {
      // Keys of arrays of tables: in a table of their own.
      const std::string table = key.path.substr(0, key.path.rfind('.'));
      const std::string leaf = key.path.substr(key.path.rfind('.') + 1);
      EXPECT_NO_THROW(load_scene_text("[[" + table + "]]\n" + leaf + " = " + key.fallback + "\n", "k.toml", ""))
          << key.path;
    } else {
      EXPECT_NO_THROW(load_scene_text(scene_for(key.path), "k.toml", "", {key.path + "=" + key.fallback}))
          << key.path << " = " << key.fallback;
    }
    ++tried;
  }
  EXPECT_GT(tried, 65);
}

TEST(SceneKeys, EveryKeyIsDocumentedAndTyped) {
  for (const KeySchema& key : scene_keys()) {
    EXPECT_FALSE(key.doc.empty()) << key.path;
    EXPECT_FALSE(type_text(key).empty()) << key.path;
    if (key.type == KeyType::choice) { EXPECT_FALSE(key.choices.empty()) << key.path; }
    if (key.data_length()) { EXPECT_GT(key.range.lo, 0.0 - 1e-300) << key.path << ": a length is not negative"; }
    EXPECT_EQ(find_scene_key(key.path), &key);
  }
}

TEST(SceneKeys, ANearMissIsNamed) {
  EXPECT_EQ(nearest_key_hint("glyphs.spaceing"), "; did you mean glyphs.spacing?");
  EXPECT_EQ(nearest_key_hint("render.widht"), "; did you mean render.width?");
  EXPECT_EQ(nearest_key_hint("something.else.entirely"), "");
  EXPECT_TRUE(is_scene_table("light.ambient_occlusion"));
  EXPECT_FALSE(is_scene_table("light.ambient"));
}

TEST(SceneKeys, AnAbsentTableStillTakesTheSchemaDefaults) {
  const SceneSpec spec = load_scene_text("", "empty.toml", "");
  EXPECT_EQ(spec.surface.isovalue, default_node(scene_key("surface.isovalue"))->value<double>());
  EXPECT_EQ(spec.shading.light_samples, default_node(scene_key("light.samples"))->value<int>());
  EXPECT_EQ(spec.pipeline.trajectory.max_steps, default_node(scene_key("trajectories.max_steps"))->value<int>());
  EXPECT_EQ(spec.output.dpi, default_node(scene_key("output.dpi"))->value<double>());
}

}  // namespace
}  // namespace hsb
