#include "field/tensor/sym3.h"

#include <cmath>

namespace hsb {

Sym3 Sym3::symmetric_part(const Mat3& t) {
  Sym3 s;
  s.xx = t(0, 0);
  s.yy = t(1, 1);
  s.zz = t(2, 2);
  s.xy = 0.5 * (t(0, 1) + t(1, 0));
  s.yz = 0.5 * (t(1, 2) + t(2, 1));
  s.xz = 0.5 * (t(0, 2) + t(2, 0));
  return s;
}

Mat3 Sym3::matrix() const {
  Mat3 m;
  m << xx, xy, xz,  //
      xy, yy, yz,   //
      xz, yz, zz;
  return m;
}

double Sym3::frobenius_norm() const {
  // Off-diagonal components appear twice in the full matrix.
  return std::sqrt(xx * xx + yy * yy + zz * zz + 2.0 * (xy * xy + yz * yz + xz * xz));
}

bool Sym3::is_finite() const {
  return std::isfinite(xx) && std::isfinite(yy) && std::isfinite(zz) && std::isfinite(xy) &&
         std::isfinite(yz) && std::isfinite(xz);
}

bool Sym3::holds_data() const {
  return is_finite() && (xx != 0.0 || yy != 0.0 || zz != 0.0 || xy != 0.0 || yz != 0.0 || xz != 0.0);
}

Sym3 operator+(const Sym3& a, const Sym3& b) {
  return {a.xx + b.xx, a.yy + b.yy, a.zz + b.zz, a.xy + b.xy, a.yz + b.yz, a.xz + b.xz};
}

Sym3 operator-(const Sym3& a, const Sym3& b) {
  return {a.xx - b.xx, a.yy - b.yy, a.zz - b.zz, a.xy - b.xy, a.yz - b.yz, a.xz - b.xz};
}

Sym3 operator*(double s, const Sym3& a) {
  return {s * a.xx, s * a.yy, s * a.zz, s * a.xy, s * a.yz, s * a.xz};
}

}  // namespace hsb
