#pragma once
// A plain triangle mesh: the boundary surface of a data set, handed to the
// renderer as context geometry.

#include <array>
#include <cstdint>
#include <vector>

#include "base/vec3.h"

namespace hsb {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // One unit normal per vertex, for smooth shading; vertices on a sharp
  // edge are split, so a body's edges stay edges. Empty: flat shading.
  std::vector<Vec3> normals;
};

}  // namespace hsb
