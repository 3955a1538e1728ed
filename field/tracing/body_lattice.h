#pragma once
// Where the body is: a regular lattice over the data's bounds, kept where
// the field has a value (so never in a hole, outside an L, or in a mask's
// NaN). It measures the body (its volume, or its area for a 2-D result)
// and gives evenly spaced seeding its pool of seeds.

#include <functional>
#include <optional>
#include <vector>

#include "base/box3.h"

namespace hsb {

// The field's magnitude at a point, or nothing where it has no value.
using MagnitudeSampler = std::function<std::optional<double>(const Vec3&)>;

struct BodyLattice {
  std::vector<Vec3> points;      // lattice points inside the body
  std::vector<double> magnitudes;  // the field's magnitude at each
  double spacing = 0.0;          // between neighbouring lattice points
  int dimensions = 3;            // 2 for a 2-D result (or a flat body)
  double measure = 0.0;          // the body's volume (area in 2-D)
};

// A lattice of about `target` points over `bounds` (cells of equal sides;
// an axis too thin for a cell gets one layer, at its middle, and does not
// count as a dimension; so does `plane_axis`, a 2-D result's normal). A
// body that fills little of its bounds (a thin rod on a diagonal) would
// keep too few points: the lattice is refined, up to `limit` points, until
// `wanted` fall inside. Sampled in parallel; the result does not depend on
// the thread count.
// The median of the lattice's positive, finite magnitudes (0 if none):
// the magnitude typical of the body.
double median_magnitude(const BodyLattice& body);

BodyLattice lattice_in_body(const Box3& bounds, const MagnitudeSampler& magnitude, std::optional<int> plane_axis,
                            std::size_t target = 32768, std::size_t wanted = 4096, std::size_t limit = 1 << 20);

}  // namespace hsb
