#include "field/tracing/seeding.h"

#include <stdexcept>

namespace hsb {

std::vector<Vec3> grid_seeds(const Vec3& corner, const Vec3& edge_u, const Vec3& edge_v, int n,
                             int m) {
  if (n < 1 || m < 1) throw std::invalid_argument("grid seeds: n and m must be >= 1");
  std::vector<Vec3> seeds;
  seeds.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(m));
  for (int j = 0; j < m; ++j) {
    const double b = (j + 0.5) / m;
    for (int i = 0; i < n; ++i) {
      const double a = (i + 0.5) / n;
      seeds.push_back(corner + a * edge_u + b * edge_v);
    }
  }
  return seeds;
}

}  // namespace hsb
