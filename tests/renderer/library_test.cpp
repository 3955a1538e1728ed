// The library's four calls (renderer/library/hyperstreamball.h): the
// picture they write is the command line's, pixel for pixel, whether the
// command line streamed it or not; a cancelled render writes nothing and
// leaves the prepared scene ready to render again.

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <atomic>
#include <filesystem>

#include "renderer/app/render_job.h"
#include "renderer/library/hyperstreamball.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

const std::string kFig07 = std::string(HSB_SOURCE_DIR) + "/scenes/fig07_point_load_normalized.toml";
const std::vector<std::string> kSmall = {"render.width=120", "render.height=90", "render.samples=1"};

std::vector<float> pixels_of(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
  in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data());
  return pixels;
}

TEST(Library, WritesTheCommandLinesPicture) {
  const auto dir = test_temp_dir("library", true);
  // With the colour bar (written whole) and without (streamed as rendered).
  for (const std::string bar : {"true", "false"}) {
    std::vector<std::string> overrides = kSmall;
    overrides.push_back("output.colorbar=" + bar);
    const RenderSummary cli = run_render_job({kFig07, overrides, (dir / ("cli" + bar)).string()});
    const std::unique_ptr<Prepared> prepared = prepare(load(kFig07, overrides));
    const Picture picture = render(*prepared);
    EXPECT_EQ(display_rgba(picture, *prepared).size(), std::size_t(120 * 90 * 4));
    const std::string path = (dir / ("library" + bar + ".png")).string();
    write(picture, *prepared, path);
    const std::vector<float> ours = pixels_of(path);
    ASSERT_FALSE(ours.empty());
    EXPECT_EQ(ours, pixels_of(cli.image_path)) << "colour bar " << bar;
  }
}

TEST(Library, ACancelledRenderWritesNothingAndThePreparedSceneRendersAgain) {
  const std::unique_ptr<Prepared> prepared = prepare(load(kFig07, kSmall));
  std::atomic<bool> cancel{false};
  RenderControl control;
  control.cancel = &cancel;
  control.progress = [&](double) { cancel = true; };
  EXPECT_THROW(render(*prepared, control), RenderCancelled);
  cancel = false;
  control.progress = nullptr;
  const Picture again = render(*prepared, control);
  const Picture fresh = render(*prepare(load(kFig07, kSmall)));
  EXPECT_EQ(again.rendered.film.data(Plane::color), fresh.rendered.film.data(Plane::color));
}

TEST(Library, LoadsSceneText) {
  const std::unique_ptr<Prepared> prepared =
      prepare(load_text("[render]\nwidth = 40\nheight = 30\nsamples = 1\n", "text.toml"));
  const Picture picture = render(*prepared);
  EXPECT_EQ(picture.rendered.film.width(), 40);
  EXPECT_GT(prepared->scene->field.sources.size(), 0u);
}

}  // namespace
}  // namespace hsb
