// Image files: formats, bit depths, metadata, and never a partial file.

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "renderer/image/image_output.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

std::filesystem::path temp_dir() {
  return test_temp_dir("image_test");
}

ImageToWrite gradient(int channels) {
  ImageToWrite image;
  image.width = 16;
  image.height = 8;
  image.channels = channels;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < channels; ++c) image.pixels.push_back(float(x) / 15.0f * (c == 3 ? 1.0f : 0.5f));
  image.metadata = {{"Software", "Hyperstreamball test"}, {"hsb:scene_sha1", "abc123"}};
  return image;
}

TEST(ImageOutput, PngAt8And16BitsWithMetadata) {
  for (int bits : {8, 16}) {
    ImageToWrite image = gradient(4);
    image.bit_depth = bits;
    const std::string path = (temp_dir() / ("g" + std::to_string(bits) + ".png")).string();
    write_image(image, path);
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.width, 16);
    EXPECT_EQ(spec.format, bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
    EXPECT_EQ(spec.get_string_attribute("Software"), "Hyperstreamball test");
    EXPECT_EQ(spec.get_string_attribute("hsb:scene_sha1"), "abc123");
    std::vector<float> back(16 * 8 * 4);
    ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, back.data()));
    EXPECT_NEAR(back[15 * 4], 0.5f, bits == 16 ? 1e-4f : 4.0f / 255.0f);
  }
}

TEST(ImageOutput, ExrKeepsFloatsBeyondOne) {
  ImageToWrite image = gradient(5);
  image.channel_names = {"R", "G", "B", "A", "Z"};
  image.bit_depth = 32;
  image.pixels[0] = 7.5f;
  const std::string path = (temp_dir() / "g.exr").string();
  write_image(image, path);
  auto in = OIIO::ImageInput::open(path);
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().nchannels, 5);
  std::vector<float> back(16 * 8 * 5);
  ASSERT_TRUE(in->read_image(0, 0, 0, 5, OIIO::TypeDesc::FLOAT, back.data()));
  EXPECT_FLOAT_EQ(back[0], 7.5f);
}

TEST(ImageOutput, FailureLeavesNoFileBehind) {
  const auto dir = temp_dir() / "fail";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  EXPECT_THROW(write_image(gradient(4), (dir / "x.bmpx").string()), std::runtime_error);
  ImageToWrite bad = gradient(4);
  bad.bit_depth = 12;
  EXPECT_THROW(write_image(bad, (dir / "x.png").string()), std::runtime_error);
  EXPECT_THROW(write_image(gradient(4), (dir / "missing-folder" / "x.png").string()), std::runtime_error);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace hsb
