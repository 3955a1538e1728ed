#pragma once
// A vector field (a flow's velocity) and a scalar field (a temperature, or
// any array a data file carries for colouring), sampled anywhere in their
// domain, as TensorField is for tensors.

#include <memory>
#include <optional>

#include "field/box3.h"
#include "field/mesh_locator.h"

namespace hsb {

class VectorField {
 public:
  virtual ~VectorField() = default;
  virtual Box3 bounds() const = 0;
  // The vector at `x`, or nothing outside the domain. Never non-finite.
  virtual std::optional<Vec3> sample(const Vec3& x) const = 0;
};

class ScalarField {
 public:
  virtual ~ScalarField() = default;
  virtual std::optional<double> sample(const Vec3& x) const = 0;
};

// The two on a VTK data set's locator.
class MeshVectorField final : public VectorField {
 public:
  MeshVectorField(std::shared_ptr<const MeshLocator> locator, std::vector<Vec3> values, ValueLocation location)
      : values_(std::move(locator), std::move(values), location) {}
  Box3 bounds() const override { return values_.bounds(); }
  std::optional<Vec3> sample(const Vec3& x) const override { return values_.sample(x); }
  const std::vector<Vec3>& values() const { return values_.values(); }

 private:
  MeshArray<Vec3> values_;
};

class MeshScalarField final : public ScalarField {
 public:
  MeshScalarField(std::shared_ptr<const MeshLocator> locator, std::vector<double> values, ValueLocation location)
      : values_(std::move(locator), std::move(values), location) {}
  std::optional<double> sample(const Vec3& x) const override { return values_.sample(x); }

 private:
  MeshArray<double> values_;
};

}  // namespace hsb
