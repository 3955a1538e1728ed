// What writing a picture costs alone: hsb's image writer (write_image, the
// file a render ends with) on a picture it made, timed apart from the
// render, the colour transform and the annotations.
//
//   png_write_bench PICTURE [RUNS]     (RUNS: 7 by default)
//
// Reads PICTURE (a PNG hsb wrote, e.g. Teem's helix at 2000²: see the
// README), then writes its pixels again as an 8-bit PNG of the same
// channels RUNS times after one write that loads the image module, and
// prints the median and fastest write, megapixels a second and the file's
// size. Measures; never fails on a number.

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>
#include <string>
#include <vector>

#include "renderer/image/image_output.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: png_write_bench PICTURE [RUNS]\n");
    return 2;
  }
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 7;
  auto in = OIIO::ImageInput::open(argv[1]);
  if (!in) {
    std::fprintf(stderr, "png_write_bench: %s: %s\n", argv[1], OIIO::geterror().c_str());
    return 1;
  }
  const OIIO::ImageSpec& spec = in->spec();
  hsb::ImageToWrite image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.pixels.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    std::fprintf(stderr, "png_write_bench: %s: %s\n", argv[1], in->geterror().c_str());
    return 1;
  }
  in->close();

  const std::string out =
      (std::filesystem::temp_directory_path() / ("png_write_bench_" + std::to_string(::getpid()) + ".png")).string();
  hsb::write_image(image, out);  // loads the image module: not a write's cost
  std::vector<double> seconds;
  for (int i = 0; i < runs; ++i) {
    const auto start = std::chrono::steady_clock::now();
    hsb::write_image(image, out);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  const auto bytes = std::filesystem::file_size(out);
  std::filesystem::remove(out);
  std::sort(seconds.begin(), seconds.end());
  const double median = seconds[seconds.size() / 2];
  const double megapixels = double(image.width) * double(image.height) * 1e-6;
  std::printf("%s: %d × %d, %d channels, 8 bits: write median %.3f s, fastest %.3f s (%d runs), %.1f MP/s, %.0f kB\n",
              argv[1], image.width, image.height, image.channels, median, seconds.front(), runs, megapixels / median,
              double(bytes) * 1e-3);
  return 0;
}
