#include "renderer/image/dither.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace hsb {
namespace {

// The pattern repeats every kTile pixels each way: the offsets are looked
// up, not computed, and a repeat of 64 pixels in a grain of one level's
// amplitude is invisible.
constexpr int kTile = 64;
// Each channel reads the pattern shifted, so the grain of red, green and
// blue does not line up into grey specks.
constexpr int kChannelShift[4] = {0, 21, 42, 9};

std::array<float, kTile * kTile> gradient_noise() {
  std::array<float, kTile * kTile> tile{};
  for (int y = 0; y < kTile; ++y)
    for (int x = 0; x < kTile; ++x) {
      const double inner = 0.06711056 * x + 0.00583715 * y;
      const double value = 52.9829189 * (inner - std::floor(inner));
      tile[std::size_t(y * kTile + x)] = float(value - std::floor(value));
    }
  return tile;
}

const std::array<float, kTile * kTile>& noise_tile() {
  static const std::array<float, kTile * kTile> tile = gradient_noise();
  return tile;
}

// Channel c's row of the tile for picture row y, and the column in it of
// picture column x: the offset of pixel (x, y) is row[column].
const float* tile_row(const std::array<float, kTile * kTile>& tile, int y, int c) {
  return &tile[std::size_t(((y + kChannelShift[c % 4]) % kTile) * kTile)];
}
int tile_column(int x, int c) { return (x + 3 * kChannelShift[c % 4]) % kTile; }

}  // namespace

float dither_offset(int x, int y, int c) { return tile_row(noise_tile(), y, c)[tile_column(x, c)]; }

void dithered_8bit(const PixelRows& rows, int alpha_channel, std::vector<unsigned char>& bytes) {
  const std::size_t in_row = std::size_t(rows.width) * std::size_t(rows.in_channels);
  const std::size_t out_row = std::size_t(rows.width) * std::size_t(rows.channels);
  bytes.resize(out_row * std::size_t(rows.rows));
  const std::array<float, kTile * kTile>& tile = noise_tile();
  tbb::parallel_for(tbb::blocked_range<int>(0, rows.rows, rows_per_task(rows.width)), [&](const tbb::blocked_range<int>& band) {
    for (int r = band.begin(); r < band.end(); ++r) {
      const int y = rows.first_row + r;
      const float* in = rows.pixels + std::size_t(r) * in_row;
      unsigned char* out = bytes.data() + std::size_t(r) * out_row;
      for (int c = 0; c < rows.channels; ++c) {
        const float* noise = tile_row(tile, y, c);
        for (int x = 0; x < rows.width; ++x) {
          const float v = clamped_to_unit(in[std::size_t(x) * std::size_t(rows.in_channels) + std::size_t(c)]);
          const float offset = c == alpha_channel ? 0.5f : noise[tile_column(x, c)];
          out[std::size_t(x) * std::size_t(rows.channels) + std::size_t(c)] =
              (unsigned char)std::min(255.0f, v * 255.0f + offset);
        }
      }
    }
  });
}

}  // namespace hsb
