#pragma once
// What a glyph hit knows of the sources around it, for the occlusion rays
// that leave it (key-light shadows, ambient occlusion). Every shape's u is
// convex in space (a norm of W_s(x − c), glyph_shape.h), so its tangent
// plane at the hit x bounds it from below everywhere:
//   u(p) ≥ u(x) + ∇u(x)·(p − x)
// (where u has a crease ∇u is a subgradient, which bounds it as well).
// Along an occlusion ray p(t) = o + t d that is a line in t, the form of
// bound the glyph-shape tracer keeps for each source it has evaluated
// (shape_trace.cpp). So the ray's walk starts from these planes instead of
// evaluating every source around its start: on fig08 as superquadrics
// those first probes were a third of all the render's gauges, six times
// over for each hit (four key-light rays and two ambient ones), at points a
// shadow offset apart.

#include <cstdint>
#include <vector>

#include "base/vec3.h"

namespace hsb {

struct SupportPlanes {
  struct Plane {
    std::uint32_t rank;  // the source's spatial rank (spatial_rank.h)
    double u;            // at `at`
    Vec3 gradient;       // ∇u at `at`, in world units
  };
  Vec3 at = Vec3::Zero();
  // In rank order, the order a ray's spans that all begin where it starts
  // are kept in (FieldRay::prepare_shape_rays): one pass over both pairs
  // them.
  std::vector<Plane> planes;
};

}  // namespace hsb
