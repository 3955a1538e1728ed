#include "renderer/image/display_image.h"

#include <tbb/parallel_for.h>

#include <stdexcept>
#include <string>

namespace hsb {
namespace {

// `pixels` of the film's colour (RGB, premultiplied) and alpha as straight
// RGBA in `rgba`, which may be `color` itself with room for the fourth
// channel: widened from the last pixel back, pixel i's RGB at 3i moves to
// 4i, at or after it, so no pixel is overwritten before it has moved.
void straight_rgba(const float* color, const float* alpha, std::size_t pixels, bool keep_alpha, float* rgba) {
  for (std::size_t i = pixels; i-- > 0;) {
    const float a = keep_alpha ? alpha[i] : 1.0f;
    for (std::size_t c = 3; c-- > 0;) rgba[i * 4 + c] = a > 0.0f ? color[i * 3 + c] / a : 0.0f;
    rgba[i * 4 + 3] = a;
  }
}

// Straight RGBA through the display transform, then premultiplied again.
void to_display(std::vector<float>& rgba, int width, int rows, const ColorManagement& color) {
  color.apply_display(rgba, width, rows);
  tbb::parallel_for(std::size_t{0}, rgba.size() / 4, [&](std::size_t i) {
    for (std::size_t c = 0; c < 3; ++c) rgba[i * 4 + c] *= rgba[i * 4 + 3];
  });
}

}  // namespace

std::vector<float> display_pixels(Film&& film, const ColorManagement& color, bool keep_alpha) {
  const std::size_t pixels = std::size_t(film.width()) * std::size_t(film.height());
  const std::vector<float> alpha = film.take(Plane::alpha);
  std::vector<float> rgba = film.take(Plane::color);
  rgba.resize(pixels * 4);  // within the film's reserve: no copy
  straight_rgba(rgba.data(), alpha.data(), pixels, keep_alpha, rgba.data());
  to_display(rgba, film.width(), film.height(), color);
  return rgba;
}

void display_rows(const Film& film, int first, int last, const ColorManagement& color, bool keep_alpha,
                  std::vector<float>& rgba) {
  if (first / film.rows_held() != (last - 1) / film.rows_held())
    throw std::invalid_argument("display_rows: rows " + std::to_string(first) + " to " + std::to_string(last) +
                                " are not together in the film's window");
  const std::size_t pixels = std::size_t(film.width()) * std::size_t(last - first);
  rgba.resize(pixels * 4);
  straight_rgba(film.at(Plane::color, 0, first), film.at(Plane::alpha, 0, first), pixels, keep_alpha, rgba.data());
  to_display(rgba, film.width(), last - first, color);
}

float ink_over(const std::vector<float>& rgba, int width, int x, int y) {
  const float* p = &rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
  if (p[3] < 0.5f) return 0.0f;
  const float luminance = (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / p[3];
  return luminance > 0.5f ? 0.0f : 1.0f;
}

}  // namespace hsb
