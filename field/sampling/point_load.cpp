#include "field/sampling/point_load.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsb {

namespace {

constexpr double kPi = 3.14159265358979323846;

void validate(const PointLoadSpec& spec) {
  const Box3& b = spec.bounds;
  if (!b.lo.allFinite() || !b.hi.allFinite() || !(b.lo.array() < b.hi.array()).all())
    throw std::invalid_argument("point load: bounds must be finite with lo < hi on every axis");
  if (!std::isfinite(spec.load)) throw std::invalid_argument("point load: load must be finite");
  if (!std::isfinite(spec.poisson_ratio))
    throw std::invalid_argument("point load: poisson_ratio must be finite");
  if (spec.singular_radius && (!std::isfinite(*spec.singular_radius) || *spec.singular_radius <= 0.0))
    throw std::invalid_argument("point load: singular_radius must be finite and > 0");
}

}  // namespace

double default_singular_radius(const Box3& bounds) { return 1e-3 * bounds.diagonal(); }

PointLoadField::PointLoadField(const PointLoadSpec& spec)
    : spec_(spec),
      load_point_(0.0, 0.0, 0.0),
      singular_radius_(0.0) {
  validate(spec_);
  const Vec3 c = spec_.bounds.centre();
  load_point_ = Vec3(c.x(), c.y(), spec_.bounds.hi.z());
  singular_radius_ = spec_.singular_radius.value_or(default_singular_radius(spec_.bounds));
}

Sym3 PointLoadField::stress(const Vec3& p) const {
  // The textbook solution (Saada, via vtkPointLoad) is written in a frame
  // with its origin at the load and z measuring depth. VTK gets there by a
  // half-turn about x (y and z flipped), a proper rotation, so the result
  // can be rotated back exactly below.
  double x = p.x() - load_point_.x();
  double y = load_point_.y() - p.y();
  // Above the surface there is no material; using the surface value keeps
  // stress() total without inventing a continuation.
  double z = std::max(0.0, load_point_.z() - p.z());

  double rho = std::sqrt(x * x + y * y + z * z);
  if (rho < singular_radius_) {
    // The stress grows like 1/ρ²; inside the small ball we return the value
    // on its surface in the same direction, so the field stays finite and
    // keeps its orientation. At the load point itself "straight down" is the
    // only direction that respects the axial symmetry.
    if (rho == 0.0) {
      z = singular_radius_;
    } else {
      const double s = singular_radius_ / rho;
      x *= s;
      y *= s;
      z *= s;
    }
    rho = singular_radius_;
  }

  // P < 0 for a load pushing into the half-space: with tension positive the
  // stresses beneath it come out compressive.
  const double P = -spec_.load;
  const double n = 1.0 - 2.0 * spec_.poisson_ratio;
  const double rho2 = rho * rho;
  const double rho3 = rho2 * rho;
  const double rho5 = rho2 * rho3;
  const double rho_plus_z = rho + z;  // > 0: z ≥ 0 and ρ > 0
  const double two_pi = 2.0 * kPi;
  const double a = P / (two_pi * rho2);
  const double shear_factor = (2.0 * rho + z) / (rho * rho_plus_z * rho_plus_z);

  const double sx =
      a * (3.0 * z * x * x / rho3 - n * (z / rho - rho / rho_plus_z + x * x * shear_factor));
  const double sy =
      a * (3.0 * z * y * y / rho3 - n * (z / rho - rho / rho_plus_z + y * y * shear_factor));
  const double sz = 3.0 * P * z * z * z / (two_pi * rho5);
  const double txy = a * (3.0 * x * y * z / rho3 - n * x * y * shear_factor);
  const double txz = 3.0 * P * x * z * z / (two_pi * rho5);
  const double tyz = 3.0 * P * y * z * z / (two_pi * rho5);

  // Back to world axes: R = diag(1, −1, −1), σ_world = R σ_local Rᵀ flips
  // the sign of every shear component that pairs x with a flipped axis.
  Sym3 s;
  s.xx = sx;
  s.yy = sy;
  s.zz = sz;
  s.xy = -txy;
  s.xz = -txz;
  s.yz = tyz;
  return s;
}

std::optional<Sym3> PointLoadField::sample(const Vec3& x) const {
  if (!spec_.bounds.contains(x)) return std::nullopt;
  return stress(x);
}

}  // namespace hsb
