#include "renderer/render/film.h"

#include "base/huge_pages.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsb {

const PlaneInfo& plane_info(Plane plane) {
  static const std::array<PlaneInfo, kPlaneCount> table{{
      {Plane::color, "color", 3, Combine::filtered_average, {"R", "G", "B"}, 0.0f},
      {Plane::alpha, "alpha", 1, Combine::filtered_average, {"A", nullptr, nullptr}, 0.0f},
      {Plane::depth, "depth", 1, Combine::nearest, {"Z", nullptr, nullptr}, INFINITY},
      {Plane::normal, "normal", 3, Combine::filtered_average, {"N.X", "N.Y", "N.Z"}, 0.0f},
      {Plane::scalar, "scalar", 1, Combine::filtered_average, {"scalar", nullptr, nullptr}, NAN},
      {Plane::id, "id", 1, Combine::dominant, {"id", nullptr, nullptr}, -1.0f},
  }};
  return table.at(std::size_t(plane));
}

Film::Film(int width, int height, const std::vector<Plane>& planes, int window_rows)
    : width_(width), height_(height), rows_held_(window_rows > 0 ? std::min(window_rows, height) : height) {
  if (width < 1 || height < 1) throw std::invalid_argument("a film needs at least one pixel");
  const std::size_t pixels = std::size_t(width) * std::size_t(rows_held_);
  // Colour keeps room for a fourth channel: the display image widens it to
  // RGBA where it stands (display_image.h). Reserved, not touched, the room
  // is no resident memory while the picture renders.
  const auto allocate = [&](Plane p) {
    const PlaneInfo& info = plane_info(p);
    const std::size_t values = pixels * std::size_t(info.channels);
    assign_on_huge_pages(data_[std::size_t(p)], values, info.empty, p == Plane::color ? pixels * 4 : values);
  };
  allocate(Plane::color);
  allocate(Plane::alpha);
  for (Plane p : planes) allocate(p);
}

std::vector<Plane> Film::planes() const {
  std::vector<Plane> present;
  for (int p = 0; p < kPlaneCount; ++p)
    if (has(Plane(p))) present.push_back(Plane(p));
  return present;
}

}  // namespace hsb
