// Image files: formats, bit depths, metadata, and never a partial file.

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#include <algorithm>
#include <atomic>
#include <filesystem>

#include "renderer/image/image_io_module.h"
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

// The 8-bit picture is dithered and quantised in bands on every core; its
// bytes must be those OIIO's writer makes of the same floats with
// oiio:dither on one, alpha (premultiplied, undone by the PNG writer) included.
TEST(ImageOutput, EightBitsAreOiiosOwnDitheredBytes) {
  ImageToWrite image;
  image.width = 301;  // not a multiple of any band or tile
  image.height = 157;
  image.channels = 4;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float alpha = float((x * 7 + y * 3) % 101) / 100.0f;
      const float shade = 0.25f + 0.5f * float(x) / float(image.width) + 0.003f * float(y % 5);  // a smooth ramp
      for (float v : {shade, 1.0f - shade, 0.5f * shade}) image.pixels.push_back(v * alpha);
      image.pixels.push_back(alpha);
    }
  const std::string ours = (temp_dir() / "ours.png").string(), oiio = (temp_dir() / "oiio.png").string();
  write_image(image, ours);
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  spec.alpha_channel = 3;
  spec.attribute("oiio:dither", 1);
  auto out = OIIO::ImageOutput::create(oiio);
  ASSERT_TRUE(out && out->open(oiio, spec) && out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) &&
              out->close());
  std::vector<unsigned char> a(image.pixels.size()), b(image.pixels.size());
  for (auto [path, bytes] : {std::pair{ours, &a}, std::pair{oiio, &b}}) {
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in);
    ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, bytes->data()));
  }
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
  EXPECT_EQ(differing, 0u);  // without the same dither, most would differ
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

// A thread made while the image module loads waits for the loader to
// end, so a render's first parallel loop stalled behind the load. The
// preload makes the thread pool's threads first: as soon as it returns,
// every worker has joined the pool. (ctest runs each test in a process
// of its own, where nothing has started the pool before.)
TEST(ImageOutput, PreloadMakesThePoolsThreadsBeforeLoading) {
  struct Joined : tbb::task_scheduler_observer {
    std::atomic<int> workers{0};
    Joined() { observe(true); }
    ~Joined() override { observe(false); }
    void on_scheduler_entry(bool is_worker) override { workers += is_worker; }
  } joined;
  const int pool = int(std::min<std::size_t>(
      std::size_t(tbb::this_task_arena::max_concurrency()),
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
  preload_image_io();
  const int workers = joined.workers.load();
  finish_image_io_preload();
  EXPECT_EQ(workers, pool - 1);
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
