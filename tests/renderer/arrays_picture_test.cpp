// A picture of data handed over as arrays (field/reading/data_arrays.h)
// is the picture of the same data in a file, and its metadata names the
// arrays by their hash where a file's picture names the file's.

#include <gtest/gtest.h>

#include <memory>

#include "field/reading/data_arrays.h"
#include "renderer/library/picture_output.h"
#include "renderer/library/pinned_scene.h"
#include "renderer/library/prepared_scene.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/render_image.h"
#include "tests/data_arrays_of.h"

namespace hsb {
namespace {

const std::string kCylinder = std::string(HSB_SOURCE_DIR) + "/scenes/data/cylinder_stress_coarse.vtu";
const std::vector<std::string> kSmall = {"render.width=96", "render.height=72", "render.samples=1"};

RenderOutput rendered(const PreparedScene& p) {
  static const EmbreeDevice device;
  const RayScene rays(device, p.field, p.trace, p.context);
  return render_image(rays, p.camera, p.shading, p.render);
}

TEST(ArraysPicture, IsTheFilesPictureAndNamesTheArrays) {
  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> from_file = prepare_scene(load_scene_or_data_file(kCylinder, kSmall), color);
  SceneSpec spec = load_scene_or_data_file(kCylinder, kSmall);
  const auto arrays = std::make_shared<const DataArrays>(data_arrays_of(kCylinder, "arrays"));
  spec.pipeline.data.file.arrays = arrays;
  spec.pipeline.data.file.path = "arrays";
  const std::unique_ptr<PreparedScene> from_arrays = prepare_scene(std::move(spec), color);
  EXPECT_EQ(rendered(*from_arrays).film.data(Plane::color), rendered(*from_file).film.data(Plane::color));
  const auto metadata = picture_metadata(from_arrays->spec, "", pinned_scene_toml(*from_arrays), color);
  EXPECT_EQ(metadata.at("hsb:data_sha1"), arrays_sha1(*arrays));
  EXPECT_EQ(scene_sha1(from_arrays->spec).size(), 40u);
}

}  // namespace
}  // namespace hsb
