// Every data set the project ships, rendered as a new user would: a scene
// that names only the file. Each must give a useful picture: not blank,
// glyphs neither a speck nor the whole frame, the camera outside every
// glyph; and export and info must work on it.

#include <gtest/gtest.h>

#include <filesystem>

#include "field/reading/data_formats.h"
#include "field/reading/data_info.h"
#include "renderer/app/export_job.h"
#include "renderer/library/pinned_scene.h"
#include "renderer/library/prepared_scene.h"
#include "renderer/render/ray_scene.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> data_files() {
  std::vector<std::string> files;
  // Every file of a format hsb reads, pieces and steps of the formats' sets included.
  for (const char* folder : {"/scenes/data", "/scenes/data/generated", "/scenes/data/formats"})
    if (fs::is_directory(std::string(HSB_SOURCE_DIR) + folder))
      for (const auto& entry : fs::directory_iterator(std::string(HSB_SOURCE_DIR) + folder))
        if (entry.is_regular_file() && is_readable_data_file(entry.path().string()))
          files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

class DataSet : public ::testing::TestWithParam<std::string> {};

TEST_P(DataSet, ASceneNamingOnlyTheFileGivesAUsefulPicture) {
  const std::string file = GetParam();
  // The glyphs alone (no box or shell) on nothing, so the film's alpha is
  // their coverage.
  SceneSpec spec = scene_for_data_file(file, {"render.width=192", "render.height=192", "render.samples=1",
                                              "render.box=false", "render.shell=false", "render.background=transparent"});
  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> p = prepare_scene(std::move(spec), color);
  ASSERT_GT(p->field.sources.size(), 20u) << "hardly any glyphs";
  for (const std::string& w : p->warnings) {
    EXPECT_EQ(w.find("larger than the whole data set"), std::string::npos) << w;
    EXPECT_EQ(w.find("camera is inside"), std::string::npos) << w;
  }
  EXPECT_LT(field_value(p->field, p->camera.position), p->field.isovalue) << "the camera is inside a glyph";

  static const EmbreeDevice device;
  const RayScene scene(device, p->field, p->trace, p->context);
  const RenderOutput out = render_image(scene, p->camera, p->shading, p->render);
  double covered = 0.0;
  for (const float a : out.film.data(Plane::alpha)) covered += a;
  const double fraction = covered / (double(out.film.width()) * out.film.height());
  EXPECT_GT(fraction, 0.005) << "the glyphs are a speck";
  EXPECT_LT(fraction, 0.6) << "the glyphs fill the frame";

  // Export and info on the same file.
  const fs::path dir = test_temp_dir("data_sets_test");
  const std::vector<std::string> written = run_export_job({file, {}, dir.string()});
  for (const std::string& w : written) EXPECT_GT(fs::file_size(w), 0u) << w;
  EXPECT_NE(describe_data(p->spec.pipeline.data).find("bounds"), std::string::npos);
  EXPECT_NE(pinned_scene_toml(*p).find("[glyphs]"), std::string::npos);
}

// The same scene gives the same glyphs, run after run, whatever the threads
// did: images must not change between renders.
TEST_P(DataSet, TheGlyphsAreReproducible) {
  const SceneSpec spec = scene_for_data_file(GetParam());
  const GlyphScene a = build_glyph_scene(spec.pipeline, 0.5), b = build_glyph_scene(spec.pipeline, 0.5);
  ASSERT_EQ(a.sources.size(), b.sources.size());
  for (std::size_t i = 0; i < a.sources.size(); ++i) {
    ASSERT_EQ(a.sources[i].centre, b.sources[i].centre) << "source " << i;
    ASSERT_EQ(a.sources[i].radii, b.sources[i].radii) << "source " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Shipped, DataSet, ::testing::ValuesIn(data_files()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           // The whole name: a .pvd and an .xdmf of one stem are two files.
                           std::string name = fs::path(param.param).filename().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace hsb
