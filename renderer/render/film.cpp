#include "renderer/render/film.h"

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

Film::Film(int width, int height, const std::vector<Plane>& planes) : width_(width), height_(height) {
  if (width < 1 || height < 1) throw std::invalid_argument("a film needs at least one pixel");
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  const auto allocate = [&](Plane p) {
    const PlaneInfo& info = plane_info(p);
    data_[std::size_t(p)].assign(pixels * std::size_t(info.channels), info.empty);
  };
  // Colour keeps room for a fourth channel: the display image widens it to
  // RGBA where it stands (display_image.h). Reserved, not touched, the room
  // is no resident memory while the picture renders.
  data_[std::size_t(Plane::color)].reserve(pixels * 4);
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
