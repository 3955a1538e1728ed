#pragma once
// Double-precision boxes handed to Embree's float BVH builders.

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>

#include "base/box3.h"

namespace hsb {

// How far to widen the boxes of a geometry `diagonal` across. Embree
// culls boxes with a float copy of each ray, in kernels that round
// differently on each instruction set, while the primitives here are met
// by the ray in double precision. The float ray strays from the double one
// by about 1.2e-7 of its distance from the origin; this margin covers that
// for cameras within some 80 diagonals, so a primitive the double ray meets
// is never culled, on any instruction set.
inline double bounds_margin(double diagonal) { return 1e-5 * diagonal; }

// Widens a double box by `margin` and rounds it outwards to float.
inline void store_bounds(const Box3& box, double margin, RTCBounds* out) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  out->lower_x = std::nextafter(static_cast<float>(box.lo.x() - margin), -inf);
  out->lower_y = std::nextafter(static_cast<float>(box.lo.y() - margin), -inf);
  out->lower_z = std::nextafter(static_cast<float>(box.lo.z() - margin), -inf);
  out->upper_x = std::nextafter(static_cast<float>(box.hi.x() + margin), inf);
  out->upper_y = std::nextafter(static_cast<float>(box.hi.y() + margin), inf);
  out->upper_z = std::nextafter(static_cast<float>(box.hi.z() + margin), inf);
}

}  // namespace hsb
