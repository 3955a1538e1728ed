#pragma once
// Rows of a display-referred picture on their way to a file: a band of a
// picture written as it is made, or the whole of one.

namespace hsb {

struct PixelRows {
  const float* pixels = nullptr;  // rows × width pixels of in_channels floats, top row first
  int width = 0;
  int rows = 0;
  int first_row = 0;    // the picture row of the first
  int in_channels = 4;  // floats a pixel in `pixels`
  int channels = 4;     // of them the first `channels` are written
};

}  // namespace hsb
