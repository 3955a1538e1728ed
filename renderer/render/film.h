#pragma once
// What the renderer produces before any colour management: a set of named
// planes, each made from the camera samples by its own rule.
//
//   color   R G B    scene-linear, premultiplied by alpha   filtered average
//   alpha   A        coverage (0 where the background shows through)  filtered average
//   depth   Z        camera distance of the first hit       nearest sample in the pixel
//   normal  N.X N.Y N.Z   the glyph surface's, unit         filtered average of glyph hits
//   scalar  scalar   the glyphs' colour scalar              filtered average of glyph hits
//   id      id       the source whose glyph was hit         most samples in the pixel
//
// Colour and alpha are always made; the others only when an output asks
// for them (an EXR's layers), so a large PNG carries 16 bytes a pixel.
//
// A film may hold only a window of the picture's rows: a picture written
// as it is made (render_image.h, RenderSettings::rows_done) needs a band
// of rows at a time, not 64 MB at 2000².

#include <array>
#include <cstdint>
#include <vector>

namespace hsb {

enum class Plane { color, alpha, depth, normal, scalar, id };
constexpr int kPlaneCount = 6;

enum class Combine {
  filtered_average,  // Σ w·v / Σ w over the samples under the pixel filter
  nearest,           // the smallest value among the pixel's own samples
  dominant,          // the value most of the pixel's own samples have
};

struct PlaneInfo {
  Plane plane;
  const char* name;
  int channels;
  Combine rule;
  std::array<const char*, 3> channel_names;
  float empty;  // where no sample contributes (nothing hit)
};

const PlaneInfo& plane_info(Plane plane);

class Film {
 public:
  // Colour and alpha, and any of the other `planes`, for a picture of
  // width × height pixels. With `window_rows` (> 0) the film holds that
  // many rows only: row y where row y % window_rows stands.
  Film(int width, int height, const std::vector<Plane>& planes = {}, int window_rows = 0);

  int width() const { return width_; }
  int height() const { return height_; }
  // The rows held: the height, or the window's.
  int rows_held() const { return rows_held_; }
  bool has(Plane p) const { return !data_[std::size_t(p)].empty(); }
  // The plane's values, row-major, top row first, plane_info(p).channels a
  // pixel: the rows held.
  std::vector<float>& data(Plane p) { return data_[std::size_t(p)]; }
  const std::vector<float>& data(Plane p) const { return data_[std::size_t(p)]; }
  float* at(Plane p, int x, int y) { return &data_[std::size_t(p)][offset(p, x, y)]; }
  const float* at(Plane p, int x, int y) const { return &data_[std::size_t(p)][offset(p, x, y)]; }
  // The planes present, in the order above.
  std::vector<Plane> planes() const;
  // The plane's values, moved out of the film (which no longer has it).
  std::vector<float> take(Plane p) { return std::move(data_[std::size_t(p)]); }

 private:
  std::size_t offset(Plane p, int x, int y) const {
    const std::size_t row = std::size_t(y % rows_held_);
    return (row * std::size_t(width_) + std::size_t(x)) * std::size_t(plane_info(p).channels);
  }
  int width_, height_, rows_held_;
  std::array<std::vector<float>, kPlaneCount> data_;
};

}  // namespace hsb
