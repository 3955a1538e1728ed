#pragma once
// A pinhole or orthographic camera.

#include "base/vec3.h"

namespace hsb {

enum class Projection { perspective, orthographic };

struct CameraSpec {
  Vec3 position{4, -6, 3};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 0, 1};
  Projection projection = Projection::perspective;
  double fov_degrees = 30.0;  // perspective: vertical field of view
  double height = 1.0;        // orthographic: the view's height, in world units
  // The part of the picture the view above describes, from its top-left
  // corner, as fractions of its width and height; the rest (a legend's
  // place) extends the same view to the right and below.
  double frame_width = 1.0, frame_height = 1.0;
};

struct CameraRay {
  Vec3 origin, direction;  // direction is unit
};

class Camera {
 public:
  // Throws std::invalid_argument when position equals look_at or up is
  // parallel to the view.
  Camera(const CameraSpec& spec, int width, int height);

  // The ray through image position (x, y) in pixels, (0, 0) the top-left
  // corner of the top-left pixel. Perspective rays share the eye point;
  // orthographic ones are parallel, starting on the plane through the
  // camera's position.
  CameraRay ray(double x, double y) const;

  // The side of a pixel, in world units, at `point`: at its depth along
  // the view for a perspective camera, everywhere for an orthographic one.
  double pixel_size_at(const Vec3& point) const;

 private:
  Vec3 origin_, forward_, right_, down_;
  double half_height_, half_width_;  // of the frame; perspective: tangents; orthographic: lengths
  double frame_width_, frame_height_;  // in pixels
  int width_, height_;
  Projection projection_;
};

}  // namespace hsb
