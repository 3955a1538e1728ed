#include "renderer/render/camera.h"

#include <cmath>
#include <stdexcept>

namespace hsb {

Camera::Camera(const CameraSpec& spec, int width, int height)
    : origin_(spec.position), width_(width), height_(height), projection_(spec.projection) {
  forward_ = spec.look_at - spec.position;
  if (forward_.norm() == 0.0) throw std::invalid_argument("camera position equals look_at");
  forward_.normalize();
  right_ = forward_.cross(spec.up);
  if (right_.norm() < 1e-12 * spec.up.norm()) throw std::invalid_argument("camera up is parallel to the view direction");
  right_.normalize();
  down_ = forward_.cross(right_);  // image y grows downwards
  half_height_ = projection_ == Projection::perspective ? std::tan(0.5 * spec.fov_degrees * M_PI / 180.0)
                                                         : 0.5 * spec.height;
  frame_width_ = spec.frame_width * width;
  frame_height_ = spec.frame_height * height;
  half_width_ = half_height_ * frame_width_ / frame_height_;
}

CameraRay Camera::ray(double x, double y) const {
  const double sx = (2.0 * x / frame_width_ - 1.0) * half_width_;
  const double sy = (2.0 * y / frame_height_ - 1.0) * half_height_;
  if (projection_ == Projection::orthographic) return {origin_ + sx * right_ + sy * down_, forward_};
  return {origin_, (forward_ + sx * right_ + sy * down_).normalized()};
}

double Camera::pixel_size_at(const Vec3& point) const {
  const double at_unit_depth = 2.0 * half_height_ / frame_height_;
  if (projection_ == Projection::orthographic) return at_unit_depth;
  return at_unit_depth * std::fabs((point - origin_).dot(forward_));
}

}  // namespace hsb
