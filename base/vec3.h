#pragma once
// Points, directions and 3×3 matrices: Eigen's fixed-size types, used by
// both sides (data sets and trajectories in field/, rays and cameras in
// renderer/).

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products, used wherever Vec3 is

namespace hsb {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

}  // namespace hsb
