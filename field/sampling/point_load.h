#pragma once
// Boussinesq's point load on an elastic half-space: the paper's synthetic
// data set, with the conventions of VTK's vtkPointLoad.

#include <optional>

#include "field/sampling/field.h"

namespace hsb {

struct PointLoadSpec {
  Box3 bounds{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
  // Load P applied at the centre of the top face (max z). As in vtkPointLoad,
  // a positive load pushes towards −z, so stresses below it are compressive
  // (negative).
  double load = 1.0;
  double poisson_ratio = 0.3;
  // The stress is singular at the load point. Within this distance of it the
  // field returns the stress at this distance in the same direction (straight
  // down at the point itself), so it stays finite everywhere. Automatic:
  // default_singular_radius(bounds).
  std::optional<double> singular_radius;
};

// 1e-3 of the domain's diagonal: small enough not to show, large enough to
// keep the stress within a million times its value one diagonal away.
double default_singular_radius(const Box3& bounds);

class PointLoadField final : public TensorField {
 public:
  explicit PointLoadField(const PointLoadSpec& spec);

  Box3 bounds() const override { return spec_.bounds; }
  std::optional<Sym3> sample(const Vec3& x) const override;

  // The stress at any point of the half-space below the load (no domain
  // check); used by sample() and by tests that probe outside the box.
  Sym3 stress(const Vec3& x) const;
  Vec3 load_point() const { return load_point_; }
  double singular_radius() const { return singular_radius_; }

 private:
  PointLoadSpec spec_;
  Vec3 load_point_;
  double singular_radius_;
};

}  // namespace hsb
