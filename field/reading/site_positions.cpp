#include "field/reading/site_positions.h"

namespace hsb {

SitePositions::SitePositions(const Vec3& origin, const Vec3& spacing, const Mat3& direction,
                             const std::array<int, 3>& first, const std::array<int, 3>& dims)
    : grid_(true),
      aligned_(direction == Mat3::Identity()),
      origin_(origin),
      spacing_(spacing),
      direction_(direction),
      first_{double(first[0]), double(first[1]), double(first[2])},
      nx_(std::size_t(dims[0])),
      ny_(std::size_t(dims[1])),
      count_(std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2])) {}

Vec3 SitePositions::operator[](std::size_t i) const {
  if (!grid_) return listed_[i];
  const Vec3 along((first_[0] + double(i % nx_)) * spacing_[0], (first_[1] + double(i / nx_ % ny_)) * spacing_[1],
                   (first_[2] + double(i / (nx_ * ny_))) * spacing_[2]);
  return aligned_ ? Vec3(origin_ + along) : Vec3(origin_ + direction_ * along);
}

}  // namespace hsb
