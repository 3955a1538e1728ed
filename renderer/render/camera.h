#pragma once
// A pinhole camera.

#include "field/sym3.h"

namespace hsb {

struct CameraSpec {
  Vec3 position{4, -6, 3};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 0, 1};
  double fov_degrees = 30.0;  // vertical field of view
};

class Camera {
 public:
  Camera(const CameraSpec& spec, int width, int height);

  // Direction (unit) of the ray through image position (x, y) in pixels,
  // (0, 0) the top-left corner of the top-left pixel.
  Vec3 direction(double x, double y) const;
  const Vec3& origin() const { return origin_; }

 private:
  Vec3 origin_, forward_, right_, down_;
  double half_height_, half_width_;
  int width_, height_;
};

}  // namespace hsb
