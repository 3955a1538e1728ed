#pragma once
// Whether a rectangle of the picture can see a box: the camera rays
// through a rectangle fill a pyramid (perspective, from the eye) or a
// prism (orthographic), bounded by the four planes through its corner
// rays. A box wholly outside one of them is missed by every ray through
// the rectangle, so its samples see the background without being traced
// (most of a picture of a compact data set is background).

#include "base/box3.h"
#include "renderer/render/camera.h"

namespace hsb {

// False only when no camera ray through [x0, x1] × [y0, y1] (picture
// coordinates in pixels, as Camera::ray takes them) can meet `box`. The
// box is taken a little larger than it is (1e-4 of its size and of its
// distance from the camera), far beyond the rounding of the rays Embree
// traces in single precision. An empty box (lo > hi) is seen by none.
bool rectangle_may_see(const Camera& camera, double x0, double y0, double x1, double y1, const Box3& box);

}  // namespace hsb
