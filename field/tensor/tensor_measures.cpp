#include "field/tensor/tensor_measures.h"

#include <algorithm>
#include <cmath>

namespace hsb {

namespace {
// The deviatoric eigenvalues, λ − tr/3.
Vec3 deviatoric(const Vec3& eigenvalues) { return eigenvalues - Vec3::Constant(eigenvalues.sum() / 3.0); }
}  // namespace

double fractional_anisotropy(const Vec3& eigenvalues) {
  const double whole = eigenvalues.norm();
  if (!(whole > 0.0)) return 0.0;
  return std::min(1.0, std::sqrt(1.5) * deviatoric(eigenvalues).norm() / whole);
}

double fractional_anisotropy(const Sym3& t) {
  const double mean = (t.xx + t.yy + t.zz) / 3.0;
  const double off = 2.0 * (t.xy * t.xy + t.yz * t.yz + t.xz * t.xz);
  const double whole = t.xx * t.xx + t.yy * t.yy + t.zz * t.zz + off;
  if (!(whole > 0.0)) return 0.0;
  const double deviatoric = (t.xx - mean) * (t.xx - mean) + (t.yy - mean) * (t.yy - mean) +
                            (t.zz - mean) * (t.zz - mean) + off;
  return std::min(1.0, std::sqrt(1.5 * deviatoric / whole));
}

double tensor_mode(const Vec3& eigenvalues) {
  const Vec3 d = deviatoric(eigenvalues);
  const double norm = d.norm();
  // Below round-off of the tensor itself, the deviator is noise.
  if (!(norm > 1e-12 * eigenvalues.cwiseAbs().maxCoeff())) return 0.0;
  const Vec3 unit = d / norm;
  return std::clamp(3.0 * std::sqrt(6.0) * unit[0] * unit[1] * unit[2], -1.0, 1.0);
}

WestinMeasures westin_measures(const Vec3& eigenvalues) {
  Vec3 mu = eigenvalues.cwiseAbs();
  std::sort(mu.data(), mu.data() + 3, [](double a, double b) { return a > b; });
  const double sum = mu.sum();
  WestinMeasures w;
  if (!(sum > 0.0)) return w;
  w.linear = (mu[0] - mu[1]) / sum;
  w.planar = 2.0 * (mu[1] - mu[2]) / sum;
  w.spherical = 3.0 * mu[2] / sum;
  return w;
}

}  // namespace hsb
