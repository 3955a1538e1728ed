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

// Whether eigenvalue_bounds() bounds `which`: the largest and the least
// eigenvalue.
bool bounded_without_decomposing(ColorScalar which) {
  return which == ColorScalar::lambda1 || which == ColorScalar::lambda3;
}

// Bounds [lo, hi] of the largest (λ1) or least (λ3) eigenvalue of t
// without decomposing it: a symmetric matrix's eigenvalues lie in its
// Gershgorin discs, and λ1 is at least, λ3 at most, each diagonal entry
// (Rayleigh's quotient of a coordinate axis).
std::array<double, 2> eigenvalue_bounds(const Sym3& t, ColorScalar which) {
  const double rx = std::fabs(t.xy) + std::fabs(t.xz), ry = std::fabs(t.xy) + std::fabs(t.yz),
               rz = std::fabs(t.xz) + std::fabs(t.yz);
  if (which == ColorScalar::lambda1)
    return {std::max({t.xx, t.yy, t.zz}), std::max({t.xx + rx, t.yy + ry, t.zz + rz})};
  return {std::min({t.xx - rx, t.yy - ry, t.zz - rz}), std::min({t.xx, t.yy, t.zz})};
}

}  // namespace

ColorScalar family_eigenvalue(EigenFamily family) {
  switch (family) {
    case EigenFamily::major: return ColorScalar::lambda1;
    case EigenFamily::medium: return ColorScalar::lambda2;
    case EigenFamily::minor: return ColorScalar::lambda3;
  }
  return ColorScalar::lambda1;
}

std::optional<std::array<double, 2>> data_color_extremes(const TensorField& field, ColorScalar color,
                                                         const std::vector<EigenFamily>& families) {
  if (!needs_tensors(color) || color == ColorScalar::direction || natural_range(color)) return std::nullopt;
  const std::vector<Sym3>* values = held_values(field);
  if (!values) return std::nullopt;
  // The scalars whose least and largest values bound the bar's ends: a
  // family's eigenvalue is λ1 on tension lines and λ3 on compression lines,
  // and the lowest family drawn (minor, medium, major) has the least.
  if (color == ColorScalar::family_eigenvalue && families.empty()) return std::nullopt;
  const bool by_family = color == ColorScalar::family_eigenvalue;
  const EigenFamily lowest = by_family ? *std::max_element(families.begin(), families.end()) : EigenFamily::major;
  const EigenFamily highest = by_family ? *std::min_element(families.begin(), families.end()) : EigenFamily::major;
  const ColorScalar low = by_family ? family_eigenvalue(lowest) : color,
                    high = by_family ? family_eigenvalue(highest) : color;
  using Range = std::array<double, 2>;
  const Range none{INFINITY, -INFINITY};
  const auto each_block = [&](auto&& body, auto&& join) {
    return tbb::parallel_reduce(tbb::blocked_range<std::size_t>(0, values->size(), 4096), none, body, join);
  };
  const auto joined = [](const Range& a, const Range& b) { return Range{std::min(a[0], b[0]), std::max(a[1], b[1])}; };
  // For λ1 and λ3 most tensors are decided by their bounds alone (on a
  // body's mesh or a sampled grid, all but the few near the extremes):
  // the largest lower bound of the high scalar is at most its maximum, so
  // a tensor whose upper bound stays below it cannot hold the maximum;
  // likewise for the minimum. With a margin far beyond the decomposition's
  // round-off, the extremes are the same to the bit as from every tensor.
  const bool bounded = bounded_without_decomposing(low) && bounded_without_decomposing(high);
  Range reached = none;  // [least upper bound of low, largest lower bound of high]
  if (bounded)
    reached = each_block(
        [&](const tbb::blocked_range<std::size_t>& block, Range range) {
          for (std::size_t i = block.begin(); i < block.end(); ++i) {
            const Sym3& t = (*values)[i];
            if (!t.holds_data()) continue;
            range[0] = std::min(range[0], eigenvalue_bounds(t, low)[1]);
            range[1] = std::max(range[1], eigenvalue_bounds(t, high)[0]);
          }
          return range;
        },
        joined);
  const auto margin = [](double a, double b) { return 1e-9 * (std::fabs(a) + std::fabs(b)); };
  const Range r = each_block(
      [&](const tbb::blocked_range<std::size_t>& block, Range range) {
        for (std::size_t i = block.begin(); i < block.end(); ++i) {
          const Sym3& t = (*values)[i];
          if (!t.holds_data()) continue;
          if (bounded) {
            const double low_least = eigenvalue_bounds(t, low)[0], high_most = eigenvalue_bounds(t, high)[1];
            if (low_least > reached[0] + margin(low_least, reached[0]) &&
                high_most < reached[1] - margin(high_most, reached[1]))
              continue;
          }
          const Vec3 l = eigenvalues(t);
          range[0] = std::min(range[0], color_scalar(l, low));
          range[1] = std::max(range[1], color_scalar(l, high));
        }
        return range;
      },
      joined);
  if (!(r[0] <= r[1])) return std::nullopt;
  return r;
}

std::vector<double> data_color_sample(const TensorField& field, ColorScalar color,
                                      const std::vector<EigenFamily>& families, std::size_t most) {
  std::vector<double> sample;
  if (!needs_tensors(color) || color == ColorScalar::direction || natural_range(color) || most == 0) return sample;
  const std::vector<Sym3>* values = held_values(field);
  if (!values) return sample;
  const bool by_family = color == ColorScalar::family_eigenvalue;
  const std::size_t stride = std::max<std::size_t>(1, (values->size() + most - 1) / most);
  for (std::size_t i = 0; i < values->size(); i += stride) {
    const Sym3& t = (*values)[i];
    if (!t.holds_data()) continue;
    const Vec3 l = eigenvalues(t);
    if (!by_family) sample.push_back(color_scalar(l, color));
    else
      for (EigenFamily f : families) sample.push_back(color_scalar(l, family_eigenvalue(f)));
  }
  return sample;
}

}  // namespace hsb
