#include "renderer/image/raster_stream.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <stdexcept>

#include "base/file_extension.h"
#include "renderer/image/dither.h"
#include "renderer/image/image_io_module.h"
#include "renderer/image/spare_threads.h"

namespace hsb {
namespace {

// 16-bit samples need no dither: 65,536 levels do not band. Rounded as
// OIIO rounds floats it converts itself.
void rounded_16bit(const PixelRows& rows, std::vector<std::uint16_t>& shorts) {
  const std::size_t in_row = std::size_t(rows.width) * std::size_t(rows.in_channels);
  const std::size_t out_row = std::size_t(rows.width) * std::size_t(rows.channels);
  shorts.resize(out_row * std::size_t(rows.rows));
  const tbb::blocked_range<int> all(0, rows.rows, rows_per_task(rows.width));
  tbb::parallel_for(all, [&](const tbb::blocked_range<int>& band) {
    for (int r = band.begin(); r < band.end(); ++r) {
      const float* in = rows.pixels + std::size_t(r) * in_row;
      std::uint16_t* out = shorts.data() + std::size_t(r) * out_row;
      for (int x = 0; x < rows.width; ++x)
        for (int c = 0; c < rows.channels; ++c) {
          const float v = clamped_to_unit(in[std::size_t(x) * std::size_t(rows.in_channels) + std::size_t(c)]);
          out[std::size_t(x) * std::size_t(rows.channels) + std::size_t(c)] = std::uint16_t(v * 65535.0f + 0.5f);
        }
    }
  });
}

std::string checked_path(const std::string& path, const RasterStream::Format& format) {
  const std::string ext = lower_extension(path);
  if (ext != ".png" && ext != ".tif" && ext != ".tiff")
    throw std::runtime_error(path + ": unsupported image format \"" + ext + "\" (expected .png, .tif or .tiff)");
  if (format.bit_depth != 8 && format.bit_depth != 16) throw std::runtime_error(path + ": bit depth must be 8 or 16");
  if (format.width < 1 || format.height < 1 || (format.channels != 3 && format.channels != 4))
    throw std::runtime_error(path + ": an image needs pixels, and 3 or 4 channels");
  return path;
}

}  // namespace

RasterStream::RasterStream(const std::string& path, const Format& format, Metadata metadata)
    : path_(checked_path(path, format)),
      format_(format),
      file_(path),
      writer_(run_on_spare_thread([this, metadata = std::move(metadata)] { encode_bands(metadata); })) {}

RasterStream::~RasterStream() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    abandoned_ = true;
  }
  changed_.notify_all();
  writer_.wait();
}

void RasterStream::rethrow_failure() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (failure_) std::rethrow_exception(failure_);
}

void RasterStream::write_rows(const PixelRows& rows) {
  if (rows.first_row != next_row_ || rows.rows < 1 || rows.first_row + rows.rows > format_.height ||
      rows.width != format_.width || rows.channels != format_.channels || rows.in_channels < rows.channels)
    throw std::logic_error(path_ + ": rows " + std::to_string(rows.first_row) + " to " +
                           std::to_string(rows.first_row + rows.rows) + " do not follow row " +
                           std::to_string(next_row_) + " of the picture's shape");
  Band band;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (failure_) std::rethrow_exception(failure_);
    if (!spare_.empty()) {
      band = std::move(spare_.back());
      spare_.pop_back();
    }
  }
  band.first = rows.first_row;
  band.rows = rows.rows;
  if (format_.bit_depth == 8) dithered_8bit(rows, format_.channels == 4 ? 3 : -1, band.bytes);
  else rounded_16bit(rows, band.shorts);
  next_row_ += rows.rows;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    bands_.push_back(std::move(band));
  }
  changed_.notify_all();
}

void RasterStream::finish() {
  const bool whole = next_row_ == format_.height;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    (whole ? closing_ : abandoned_) = true;
  }
  changed_.notify_all();
  writer_.wait();
  rethrow_failure();
  if (!whole)
    throw std::logic_error(path_ + ": " + std::to_string(next_row_) + " of " + std::to_string(format_.height) +
                           " rows were written");
  file_.commit();
}

void RasterStream::encode_bands(const Metadata& metadata) {
  RowEncoder* encoder = nullptr;
  const ImageIo* io = nullptr;
  try {
    ImageToWrite header;
    header.width = format_.width;
    header.height = format_.height;
    header.channels = format_.channels;
    header.bit_depth = format_.bit_depth;
    header.dpi = format_.dpi;
    if (metadata) header.metadata = metadata();
    io = &image_io();
    encoder = io->open_rows(header, lower_extension(path_), file_.path());
    for (;;) {
      Band band;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return abandoned_ || closing_ || !bands_.empty(); });
        if (abandoned_) break;
        if (bands_.empty()) {
          RowEncoder* ending = encoder;
          encoder = nullptr;  // close_rows frees it, failing or not
          lock.unlock();
          std::vector<unsigned char> memory;
          io->close_rows(ending, memory);
          if (!memory.empty()) file_.write(memory.data(), memory.size());
          return;
        }
        band = std::move(bands_.front());
        bands_.pop_front();
      }
      const void* samples = format_.bit_depth == 8 ? static_cast<const void*>(band.bytes.data()) : band.shorts.data();
      io->write_rows(encoder, band.first, band.rows, samples);
      const std::lock_guard<std::mutex> lock(mutex_);
      spare_.push_back(std::move(band));
    }
  } catch (const std::exception& e) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::string what = e.what();
    failure_ = std::make_exception_ptr(
        std::runtime_error(what.rfind(path_, 0) == 0 ? what : path_ + ": " + what));
    bands_.clear();
  }
  if (encoder) io->discard_rows(encoder);
}

}  // namespace hsb
