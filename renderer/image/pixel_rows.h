#pragma once
// Rows of a display-referred picture on their way to a file: a band of a
// picture written as it is made, or the whole of one.

#include <algorithm>

namespace hsb {

// Rows of a picture `width` wide handed to a task at a time when its pixels
// are converted on every core: some 8,000 pixels, so that a band of a few
// rows of a picture written as it is made goes to every core too.
inline int rows_per_task(int width) { return std::max(1, 8192 / std::max(1, width)); }

// A display-referred value as a file's integers take it: clamped to
// [0, 1], NaN as 0.
inline float clamped_to_unit(float value) { return value > 0.0f ? std::min(value, 1.0f) : 0.0f; }

struct PixelRows {
  const float* pixels = nullptr;  // rows × width pixels of in_channels floats, top row first
  int width = 0;
  int rows = 0;
  int first_row = 0;    // the picture row of the first
  int in_channels = 4;  // floats a pixel in `pixels`
  int channels = 4;     // of them the first `channels` are written
};

}  // namespace hsb
