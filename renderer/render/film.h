#pragma once
// A scene-linear RGBA image: what the renderer produces before any colour
// management.

#include <vector>

namespace hsb {

struct Film {
  int width = 0, height = 0;
  std::vector<float> rgba;   // width*height*4, row-major, top row first
  std::vector<float> depth;  // camera distance of the first hit, +inf where none

  Film(int w, int h) : width(w), height(h), rgba(std::size_t(w) * h * 4, 0.0f),
                       depth(std::size_t(w) * h, 0.0f) {}
  float* pixel(int x, int y) { return &rgba[(std::size_t(y) * width + x) * 4]; }
  const float* pixel(int x, int y) const { return &rgba[(std::size_t(y) * width + x) * 4]; }
};

}  // namespace hsb
