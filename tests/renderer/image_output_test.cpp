// Image files: formats, bit depths, metadata, and never a partial file.

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "renderer/image/dither.h"
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

// A flat value between two levels is drawn with both, in the proportion
// that averages to it: no byte is more than a level off, and a patch's
// mean is the value (a plain rounding would be half a level off, and a
// gradient would band).
TEST(Dither, FlatValuesAverageToThemselvesWithinALevel) {
  constexpr int kSide = 128;
  for (float level : {0.0f, 0.1f, 0.25f, 0.5f, 0.77f, 0.93f}) {
    const float value = (77.0f + level) / 255.0f;
    const std::vector<float> pixels(std::size_t(kSide * kSide * 3), value);
    std::vector<unsigned char> bytes;
    dithered_8bit({pixels.data(), kSide, kSide, 0, 3, 3}, -1, bytes);
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0;
      for (std::size_t i = std::size_t(c); i < bytes.size(); i += 3) {
        ASSERT_GE(bytes[i], 77) << "level " << level;
        ASSERT_LE(bytes[i], 78) << "level " << level;
        sum += bytes[i];
      }
      EXPECT_NEAR(sum / double(kSide * kSide), 77.0 + level, 0.01) << "level " << level << " channel " << c;
    }
  }
}

// Alpha is rounded, never dithered (an opaque picture stays opaque, a
// transparent background stays transparent); values beyond [0, 1] and NaN
// are clamped, not wrapped.
TEST(Dither, AlphaIsRoundedAndValuesClamped) {
  const std::vector<float> pixels = {1.5f, -0.2f, std::nanf(""), 1.0f,  // clamped colour, opaque
                                     0.0f, 0.0f,  0.0f,          0.0f,  // transparent
                                     0.2f, 0.2f,  0.2f,          0.5f};
  std::vector<unsigned char> bytes;
  dithered_8bit({pixels.data(), 3, 1, 0, 4, 4}, 3, bytes);
  EXPECT_EQ(bytes[0], 255);
  EXPECT_EQ(bytes[1], 0);
  EXPECT_EQ(bytes[2], 0);
  EXPECT_EQ(bytes[3], 255);
  EXPECT_EQ(bytes[7], 0);
  EXPECT_EQ(bytes[11], 128);
}

// The pattern has no low frequencies: neighbouring offsets differ, so a
// flat region reads as fine grain, and the three channels are shifted so
// their grain does not coincide.
TEST(Dither, OffsetsAreFineGrainAndDifferPerChannel) {
  double step = 0.0, same_channel = 0.0;
  int n = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 63; ++x, ++n) {
      const float o = dither_offset(x, y, 0);
      ASSERT_GE(o, 0.0f);
      ASSERT_LT(o, 1.0f);
      step += std::abs(dither_offset(x + 1, y, 0) - o);
      same_channel += std::abs(dither_offset(x, y, 1) - o) < 0.02f;
    }
  EXPECT_GT(step / n, 0.25);  // white noise: 1/3; a smooth pattern: near 0
  EXPECT_LT(same_channel / n, 0.1);
}

// The 8-bit picture a PNG holds is the dithered bytes of its floats.
TEST(ImageOutput, EightBitPngHoldsTheDitheredBytes) {
  ImageToWrite image;
  image.width = 301;  // not a multiple of any band or tile
  image.height = 157;
  image.channels = 3;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float shade = 0.25f + 0.5f * float(x) / float(image.width) + 0.003f * float(y % 5);  // a smooth ramp
      for (float v : {shade, 1.0f - shade, 0.5f * shade}) image.pixels.push_back(v);
    }
  const std::string path = (temp_dir() / "dithered.png").string();
  write_image(image, path);
  std::vector<unsigned char> read(image.pixels.size());
  auto in = OIIO::ImageInput::open(path);
  ASSERT_TRUE(in);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, read.data()));
  std::vector<unsigned char> dithered;
  dithered_8bit({image.pixels.data(), image.width, image.height, 0, 3, 3}, -1, dithered);
  EXPECT_EQ(read, dithered);
}

// A render counts what the module's load has yet to add instead of
// waiting for it: never more than a whole load, none once it is in.
TEST(ImageOutput, WhatTheLoadStillAddsEndsAtNone) {
  preload_image_io();
  const double pending = image_io_pending_bytes();
  EXPECT_GE(pending, 0.0);
  EXPECT_LE(pending, 115e6);
  finish_image_io_preload();
  EXPECT_EQ(image_io_pending_bytes(), 0.0);
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

// --skip-existing asks an old picture for the scene hash it stores
// (stored_scene_sha1): what hsb wrote says it, whole; cut short, nothing.
TEST(ImageOutput, TheStoredHashOfAPictureItWrote) {
  const auto dir = temp_dir() / "stored";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  // (A TIFF keeps no metadata of hsb's: it is always rendered again.)
  for (const char* name : {"kept.png", "kept.exr"}) {
    ImageToWrite image = gradient(4);
    if (std::string(name) == "kept.exr") image.bit_depth = 16;
    const std::string path = (dir / name).string();
    write_image(image, path);
    EXPECT_EQ(stored_scene_sha1(path), "abc123") << name;
    std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
    EXPECT_EQ(stored_scene_sha1(path), "") << name << " cut short";
  }
  EXPECT_EQ(stored_scene_sha1((dir / "absent.png").string()), "");
}

// Another format under a picture's name is not asked: OpenImageIO would
// try each of its readers on it in turn, and one takes it (here an EXR
// that says a hash, named .png).
TEST(ImageOutput, AnotherFormatUnderAPicturesNameSaysNoHash) {
  const auto dir = temp_dir() / "disguised";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ImageToWrite image = gradient(4);
  image.bit_depth = 16;
  write_image(image, (dir / "exr.exr").string());
  std::filesystem::rename(dir / "exr.exr", dir / "exr.png");
  EXPECT_EQ(stored_scene_sha1((dir / "exr.png").string()), "");
  std::ofstream(dir / "junk.png") << "not an image at all";
  EXPECT_EQ(stored_scene_sha1((dir / "junk.png").string()), "");
}

// A figure's hash is read at its two ends, whatever lies between.
TEST(ImageOutput, AFiguresHashIsReadAtItsEnds) {
  const auto dir = temp_dir() / "figures";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string hash(40, 'A'), middle(3 << 20, 'x');
  std::ofstream(dir / "f.pdf") << "%PDF-1.5\n" << middle << "\n/Subject (hsb:scene_sha1=" << std::string(40, 'B')
                               << ")\n/Keywords (hsb:scene_sha1=" << hash << "; hsb:data_sha1=)\ntrailer\n%%EOF\n";
  EXPECT_EQ(stored_scene_sha1((dir / "f.pdf").string()), hash);
  std::ofstream(dir / "f.pdf", std::ios::app) << "cut here";
  EXPECT_EQ(stored_scene_sha1((dir / "f.pdf").string()), "");
  std::ofstream(dir / "f.svg") << "<?xml version=\"1.0\"?>\n<svg width=\"8\">\n<metadata>\n<hsb:entry key=\"hsb:scene_sha1\">"
                               << hash << "</hsb:entry>\n</metadata>\n" << middle << "\n</svg>\n";
  EXPECT_EQ(stored_scene_sha1((dir / "f.svg").string()), hash);
}

// What the old picture is read for is bounded, whatever the file: a 1 GB
// PDF was read whole into memory, and a PNM header under a .png name (65535²
// pixels declared) was decoded into 17 GB. Asked in a child process whose
// address space allows a quarter of a gigabyte more than it has: either
// failed there for want of memory.
TEST(ImageOutput, TheStoredHashIsReadWithinABudget) {
  const auto dir = temp_dir() / "budget";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "huge.pdf").close();
  std::filesystem::resize_file(dir / "huge.pdf", std::uintmax_t(1) << 30);  // sparse
  std::ofstream(dir / "huge.png") << "P5\n65535 65535\n255\n";
  image_io();  // loaded here, not in the child
  const pid_t child = fork();
  if (child == 0) {
    long pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlim_t room = rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE)) + (rlim_t(256) << 20);
    const rlimit limit{room, room};
    setrlimit(RLIMIT_AS, &limit);
    try {
      const bool none = stored_scene_sha1((dir / "huge.pdf").string()).empty() &&
                        stored_scene_sha1((dir / "huge.png").string()).empty();
      _exit(none ? 0 : 2);
    } catch (...) {
      _exit(3);  // std::bad_alloc
    }
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << (WEXITSTATUS(status) == 3 ? "out of memory" : "a hash from nothing");
}

}  // namespace
}  // namespace hsb
