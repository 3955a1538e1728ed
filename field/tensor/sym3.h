#pragma once
// Symmetric second-order tensors (paper eq. 3), stored as six components.

#include "base/vec3.h"

namespace hsb {

// A symmetric 3x3 tensor. Components follow VTK's six-component order
// (XX, YY, ZZ, XY, YZ, XZ) so that data files map onto it directly.
// Interpolation happens on these components, never on eigenvectors
// (paper §4.3: eigenvectors have no sign, so blending them is meaningless).
struct Sym3 {
  double xx = 0, yy = 0, zz = 0, xy = 0, yz = 0, xz = 0;

  // The symmetric part S = (T + Tᵀ)/2 of a general tensor (paper eq. 2).
  static Sym3 symmetric_part(const Mat3& t);
  Mat3 matrix() const;
  double frobenius_norm() const;
  bool is_finite() const;
  // Finite and not all zero: a value of the data (diffusion tools write
  // exact zeros outside the brain's mask, a voxel model in its void).
  bool holds_data() const;
};

Sym3 operator+(const Sym3& a, const Sym3& b);
Sym3 operator-(const Sym3& a, const Sym3& b);
Sym3 operator*(double s, const Sym3& a);

}  // namespace hsb
