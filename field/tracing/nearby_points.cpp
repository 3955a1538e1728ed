#include "field/tracing/nearby_points.h"

#include <cmath>
#include <stdexcept>

namespace hsb {

NearbyPoints::NearbyPoints(double cell) : cell_(cell) {
  if (!(cell > 0.0) || !std::isfinite(cell)) throw std::invalid_argument("nearby points: the cell must be > 0");
}

NearbyPoints::Key NearbyPoints::key_of(const Vec3& p) const {
  return {std::int64_t(std::floor(p.x() / cell_)), std::int64_t(std::floor(p.y() / cell_)),
          std::int64_t(std::floor(p.z() / cell_))};
}

// 21 bits a coordinate: two million cells along each axis, far more than
// any separation leaves in a data set (the hash only needs neighbours to
// differ, and a wrapped key merely shares a bucket).
std::uint64_t NearbyPoints::pack(std::int64_t x, std::int64_t y, std::int64_t z) {
  constexpr std::uint64_t mask = (1u << 21) - 1;
  return (std::uint64_t(x) & mask) | ((std::uint64_t(y) & mask) << 21) | ((std::uint64_t(z) & mask) << 42);
}

void NearbyPoints::add(const Vec3& p, double tag) {
  const Key k = key_of(p);
  cells_[pack(k.x, k.y, k.z)].push_back({p, tag});
  ++count_;
}

}  // namespace hsb
