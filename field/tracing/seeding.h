#pragma once
// Where trajectories start.

#include <vector>

#include "base/vec3.h"

namespace hsb {

// An n×m grid of seeds on the parallelogram corner + a·edge_u + b·edge_v,
// a, b ∈ [0, 1]. Seeds sit at the centres of the n×m cells, so none lies
// on the rectangle's border (usually the domain's boundary).
std::vector<Vec3> grid_seeds(const Vec3& corner, const Vec3& edge_u, const Vec3& edge_v, int n,
                             int m);

}  // namespace hsb
