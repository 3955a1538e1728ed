// A picture written as it is made (raster_stream.h, RenderSettings::rows_done):
// the same file as the picture written whole, a film of one band, and no
// file at all where the writing or the render does not end.

#include <gtest/gtest.h>
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <stdexcept>

#include "renderer/image/display_image.h"
#include "renderer/image/raster_stream.h"
#include "renderer/library/picture_output.h"
#include "renderer/library/prepared_scene.h"
#include "renderer/render/ray_scene.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

// The picture's samples as 16-bit integers, whatever its bit depth.
std::vector<unsigned short> read_back(const std::string& path, int& channels) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return {};
  channels = in->spec().nchannels;
  std::vector<unsigned short> samples(in->spec().image_pixels() * std::size_t(channels));
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT16, samples.data())) return {};
  return samples;
}

// A blended pile with shadows on a ground plane, 47 rows: two whole bands
// of 16 and one of 15.
const std::string scene = "[[seeds.grid]]\ncorner = [-0.4, -0.4, 0.6]\nedge_u = [0.8, 0, 0]\nedge_v = [0, 0.8, 0]\n"
                          "n = 3\nm = 3\n[trajectories]\nfamily = \"minor\"\n[render]\nwidth = 61\nheight = 47\n"
                          "samples = 2\nground = true\n[output]\ncolorbar = false\n";

TEST(RasterStream, APictureWrittenAsItIsMadeIsThePictureWrittenWhole) {
  const std::filesystem::path dir = test_temp_dir("raster_stream", true);
  const ColorManagement color("", "");
  for (const std::string background : {"[0.2, 0.3, 0.4]", "\"transparent\""})
    for (int bits : {8, 16}) {
      const std::unique_ptr<PreparedScene> p = prepare_scene(
          load_scene_text(scene, "stream.toml", "",
                          {"render.background=" + background, "output.bit_depth=" + std::to_string(bits)}),
          color);
      ASSERT_TRUE(p->output.streams());
      static const EmbreeDevice device;
      const RayScene rays(device, p->field, p->trace, p->context);
      const bool transparent = p->shading.background_kind == BackgroundKind::transparent;
      const std::map<std::string, std::string> metadata{{"Software", "Hyperstreamball test"}};

      const std::string whole = (dir / "whole.png").string();
      RenderOutput rendered = render_image(rays, p->camera, p->shading, p->render);
      std::vector<float> rgba = display_pixels(std::move(rendered.film), color, transparent);
      write_display_picture(whole, std::move(rgba), p->render.width, p->render.height, transparent, Annotations(),
                            p->output, metadata, color);

      const std::string streamed = (dir / "streamed.png").string();
      const RasterStream::Format format = display_raster_format(p->render.width, p->render.height, p->output, transparent);
      RasterStream stream(streamed, format, [&] { return metadata; });
      RenderSettings settings = p->render;
      int bands = 0;
      std::vector<float> band;
      settings.rows_done = [&](const Film& film, int first, int last) {
        display_rows(film, first, last, color, transparent, band);
        stream.write_rows({band.data(), film.width(), last - first, first, 4, format.channels});
        ++bands;
      };
      const RenderOutput made = render_image(rays, p->camera, p->shading, settings);
      stream.finish();
      EXPECT_EQ(bands, 3);
      EXPECT_EQ(made.film.rows_held(), 16);  // a band, not the picture
      EXPECT_EQ(made.film.data(Plane::color).size(), std::size_t(61 * 16 * 3));

      int whole_channels = 0, streamed_channels = 0;
      const std::vector<unsigned short> a = read_back(whole, whole_channels);
      const std::vector<unsigned short> b = read_back(streamed, streamed_channels);
      ASSERT_FALSE(a.empty());
      EXPECT_EQ(whole_channels, transparent ? 4 : 3);
      EXPECT_EQ(streamed_channels, whole_channels);
      EXPECT_TRUE(a == b) << background << " at " << bits << " bits";
    }
}

TEST(RasterStream, RowsOutOfOrderAreRefused) {
  const std::filesystem::path dir = test_temp_dir("raster_stream_order", true);
  const std::vector<float> band(8 * 2 * 4, 0.5f);
  RasterStream stream((dir / "x.png").string(), {8, 4, 3, 8, 0.0}, nullptr);
  EXPECT_THROW(stream.write_rows({band.data(), 8, 2, 2, 4, 3}), std::logic_error);  // row 2 before row 0
  stream.write_rows({band.data(), 8, 2, 0, 4, 3});
  EXPECT_THROW(stream.write_rows({band.data(), 8, 2, 2, 4, 4}), std::logic_error);  // four channels, not three
  EXPECT_THROW(stream.finish(), std::logic_error);  // two rows of four
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

// A render that fails or is interrupted ends its stream without finish():
// neither the picture nor its temporary file is left.
TEST(RasterStream, AStreamNotFinishedLeavesNoFile) {
  const std::filesystem::path dir = test_temp_dir("raster_stream_abandoned", true);
  const std::vector<float> band(8 * 2 * 4, 0.5f);
  {
    RasterStream stream((dir / "x.png").string(), {8, 4, 4, 8, 0.0}, nullptr);
    stream.write_rows({band.data(), 8, 2, 0, 4, 4});
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(RasterStream, AFailedWriteNamesThePathAndLeavesNoFile) {
  const std::filesystem::path dir = test_temp_dir("raster_stream_failed", true);
  const std::string path = (dir / "missing-folder" / "x.png").string();
  const std::vector<float> band(8 * 4 * 4, 0.5f);
  try {
    // Refused where its temporary file is made, before any row.
    RasterStream stream(path, {8, 4, 4, 16, 0.0}, nullptr);
    stream.write_rows({band.data(), 8, 4, 0, 4, 4});
    stream.finish();
    FAIL() << "a file in a missing folder was written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace hsb
