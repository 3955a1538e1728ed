#include "field/tensor/eigensystem.h"

#include <limits>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace hsb {

Eigensystem decompose(const Sym3& s) {
  Eigensystem result;
  const Mat3 m = s.matrix();
  if (m.isZero(0.0)) return result;  // values 0, identity vectors: any basis will do

  // The iterative QL solver rather than computeDirect(): the closed-form
  // cubic loses orthogonality and accuracy near repeated eigenvalues, which
  // is exactly where tensor fields get interesting (degenerate points).
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(m);
  if (solver.info() != Eigen::Success) {
    // Only non-finite input gets here; fields never produce it.
    result.values.setConstant(std::numeric_limits<double>::quiet_NaN());
    return result;
  }

  // Eigen sorts ascending; the paper orders λ1 ≥ λ2 ≥ λ3.
  for (int k = 0; k < 3; ++k) {
    result.values(k) = solver.eigenvalues()(2 - k);
    result.vectors.col(k) = solver.eigenvectors().col(2 - k);
  }
  // Eigenvector signs are arbitrary, so choosing the third column's sign to
  // make the basis a rotation (det = +1) loses nothing and lets consumers
  // treat `vectors` as an orientation.
  result.vectors.col(2) = result.vectors.col(0).cross(result.vectors.col(1));
  return result;
}

Vec3 eigenvalues(const Sym3& s) {
  const Mat3 m = s.matrix();
  if (m.isZero(0.0)) return Vec3::Zero();
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(m, Eigen::EigenvaluesOnly);
  if (solver.info() != Eigen::Success) return Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const Vec3 ascending = solver.eigenvalues();
  return {ascending(2), ascending(1), ascending(0)};
}

}  // namespace hsb
