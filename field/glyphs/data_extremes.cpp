#include "field/glyphs/data_extremes.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "field/sampling/mesh_field.h"
#include "field/sampling/uniform_grid.h"
#include "field/tensor/eigensystem.h"

namespace hsb {

namespace {

// The tensors a field holds, where it holds them.
const std::vector<Sym3>* held_values(const TensorField& field) {
  if (const auto* mesh = dynamic_cast<const MeshField<Sym3>*>(&field)) return &mesh->values();
  if (const auto* grid = dynamic_cast<const UniformGridField*>(&field)) return &grid->values();
  return nullptr;
}

}  // namespace

std::optional<std::array<double, 2>> data_color_extremes(const TensorField& field, ColorScalar color) {
  if (!needs_tensors(color) || color == ColorScalar::direction || natural_range(color)) return std::nullopt;
  const std::vector<Sym3>* values = held_values(field);
  if (!values) return std::nullopt;
  // The scalars whose least and largest values bound the bar's ends: a
  // family's eigenvalue is λ1 on tension lines and λ3 on compression lines.
  const bool families = color == ColorScalar::family_eigenvalue;
  const ColorScalar low = families ? ColorScalar::lambda3 : color, high = families ? ColorScalar::lambda1 : color;
  using Range = std::array<double, 2>;
  const Range none{INFINITY, -INFINITY};
  const Range r = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, values->size(), 4096), none,
      [&](const tbb::blocked_range<std::size_t>& block, Range range) {
        for (std::size_t i = block.begin(); i < block.end(); ++i) {
          const Sym3& t = (*values)[i];
          if (!t.holds_data()) continue;
          const Vec3 l = eigenvalues(t);
          range[0] = std::min(range[0], color_scalar(l, low));
          range[1] = std::max(range[1], color_scalar(l, high));
        }
        return range;
      },
      [](const Range& a, const Range& b) { return Range{std::min(a[0], b[0]), std::max(a[1], b[1])}; });
  if (!(r[0] <= r[1])) return std::nullopt;
  return r;
}

}  // namespace hsb
