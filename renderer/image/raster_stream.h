#pragma once
// A PNG or TIFF written a band of rows at a time, as the picture is made.
//
// Each band is quantised where it is handed over (dithered to 8 bits, or
// rounded to 16) and encoded on a thread of the stream's own (a spare one,
// made before the image module began loading: spare_threads.h), in order,
// while the caller goes on: the picture's floats are never held whole (a
// 2000² film is 64 MB, its bytes 12), and deflating, the one step of the
// output that runs on a single core, runs beside the render instead of
// after it. The thread waits for the image module where it is still
// loading (image_io_module.h) and makes the file's metadata first, so the
// data file's SHA-1 too is taken beside the render.
//
// The file appears complete or not at all (partial_file.h): finish() puts
// it in place; a stream ended without it (an error, an interrupted render)
// leaves none.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <future>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "base/partial_file.h"
#include "renderer/image/pixel_rows.h"

namespace hsb {

class RasterStream {
 public:
  struct Format {
    int width = 0, height = 0;
    int channels = 4;   // 3 (RGB) or 4 (RGBA, straight in the file)
    int bit_depth = 8;  // 8 or 16
    double dpi = 0.0;   // written as the image's resolution when > 0
  };
  // The file's metadata, made on the stream's thread.
  using Metadata = std::function<std::map<std::string, std::string>()>;

  // Begins `path` (.png, .tif, .tiff). Throws std::runtime_error for
  // another extension or a bad format.
  RasterStream(const std::string& path, const Format& format, Metadata metadata);
  ~RasterStream();
  RasterStream(const RasterStream&) = delete;
  RasterStream& operator=(const RasterStream&) = delete;

  // The next band: `rows.first_row` follows the band before (0 first),
  // `rows.width` and `rows.channels` are the format's. Display-referred,
  // premultiplied by alpha, in [0, 1] (outside is clamped, NaN is 0).
  // Throws what the writing threw, if it failed, so the caller can stop.
  void write_rows(const PixelRows& rows);

  // Waits for every band to be written, then puts the file in place.
  // Throws std::runtime_error naming the path when anything failed.
  void finish();

 private:
  struct Band {
    int first = 0, rows = 0;
    std::vector<unsigned char> bytes;    // 8 bits
    std::vector<std::uint16_t> shorts;   // 16 bits
  };
  void encode_bands(const Metadata& metadata);  // the stream's thread
  void rethrow_failure();

  const std::string path_;
  const Format format_;
  PartialFile file_;
  int next_row_ = 0;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Band> bands_;
  std::vector<Band> spare_;  // written, their buffers kept for the bands to come
  bool closing_ = false, abandoned_ = false;
  std::exception_ptr failure_;
  std::future<void> writer_;  // last: it starts once the rest is made
};

}  // namespace hsb
