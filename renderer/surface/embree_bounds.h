#pragma once
// Double-precision boxes handed to Embree's float BVH builders.

#include <embree3/rtcore.h>

#include "base/box3.h"
#include "base/float_steps.h"

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
  out->lower_x = float_down(static_cast<float>(box.lo.x() - margin));
  out->lower_y = float_down(static_cast<float>(box.lo.y() - margin));
  out->lower_z = float_down(static_cast<float>(box.lo.z() - margin));
  out->upper_x = float_up(static_cast<float>(box.hi.x() + margin));
  out->upper_y = float_up(static_cast<float>(box.hi.y() + margin));
  out->upper_z = float_up(static_cast<float>(box.hi.z() + margin));
}

}  // namespace hsb
