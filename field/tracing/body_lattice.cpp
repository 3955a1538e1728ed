#include "field/tracing/body_lattice.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <tbb/parallel_for.h>

namespace hsb {
namespace {

// Samples the lattice with cells of side `h` over the axes that count.
BodyLattice sample_lattice(const Box3& bounds, const MagnitudeSampler& magnitude, const std::array<bool, 3>& counts,
                           double h) {
  const Vec3 size = bounds.size();
  std::array<std::size_t, 3> n{};
  for (int k = 0; k < 3; ++k) n[std::size_t(k)] = counts[std::size_t(k)] ? std::size_t(std::max(1.0, std::round(size[k] / h))) : 1;
  const std::size_t total = n[0] * n[1] * n[2];
  std::vector<std::optional<double>> values(total);
  const auto point = [&](std::size_t index) {
    const std::size_t i = index % n[0], j = (index / n[0]) % n[1], k = index / (n[0] * n[1]);
    return Vec3(bounds.lo.x() + (double(i) + 0.5) * size.x() / double(n[0]),
                bounds.lo.y() + (double(j) + 0.5) * size.y() / double(n[1]),
                bounds.lo.z() + (double(k) + 0.5) * size.z() / double(n[2]));
  };
  tbb::parallel_for(std::size_t{0}, total, [&](std::size_t index) { values[index] = magnitude(point(index)); });

  BodyLattice lattice;
  lattice.spacing = h;
  double box_measure = 1.0;
  lattice.dimensions = 0;
  for (int k = 0; k < 3; ++k)
    if (counts[std::size_t(k)]) box_measure *= size[k], ++lattice.dimensions;
  for (std::size_t index = 0; index < total; ++index)
    if (values[index]) {
      lattice.points.push_back(point(index));
      lattice.magnitudes.push_back(*values[index]);
    }
  lattice.measure = box_measure * double(lattice.points.size()) / double(total);
  return lattice;
}

}  // namespace

BodyLattice lattice_in_body(const Box3& bounds, const MagnitudeSampler& magnitude, std::optional<int> plane_axis,
                            std::size_t target, std::size_t wanted, std::size_t limit) {
  const Vec3 size = bounds.size();
  const double diagonal = bounds.diagonal();
  std::array<bool, 3> counts{};
  double box_measure = 1.0;
  int dimensions = 0;
  for (int k = 0; k < 3; ++k) {
    counts[std::size_t(k)] = size[k] > 1e-6 * diagonal && (!plane_axis || *plane_axis != k);
    if (counts[std::size_t(k)]) box_measure *= size[k], ++dimensions;
  }
  if (dimensions == 0) return sample_lattice(bounds, magnitude, counts, 1.0);
  double h = std::pow(box_measure / double(target), 1.0 / dimensions);
  // A thin axis (a plate's thickness) gets one layer, and stops counting:
  // the body is measured over the others.
  for (int k = 0; k < 3; ++k)
    if (counts[std::size_t(k)] && dimensions > 1 && size[k] < 0.5 * h) {
      counts[std::size_t(k)] = false;
      box_measure /= size[k];
      --dimensions;
      h = std::pow(box_measure / double(target), 1.0 / dimensions);
    }
  BodyLattice lattice = sample_lattice(bounds, magnitude, counts, h);
  for (std::size_t total = target; lattice.points.size() < wanted && total * (1u << dimensions) <= limit;
       total *= (1u << dimensions)) {
    h *= 0.5;
    lattice = sample_lattice(bounds, magnitude, counts, h);
  }
  return lattice;
}

double median_magnitude(const BodyLattice& body) {
  std::vector<double> positive;
  for (double m : body.magnitudes)
    if (m > 0.0 && std::isfinite(m)) positive.push_back(m);
  if (positive.empty()) return 0.0;
  const auto middle = positive.begin() + std::ptrdiff_t(positive.size() / 2);
  std::nth_element(positive.begin(), middle, positive.end());
  return *middle;
}

}  // namespace hsb
