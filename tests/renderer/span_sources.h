#pragma once
// The sources of a tracer's spans, sorted: what two ways of collecting a
// ray's spans (a list of nearby sources, a traversal of the span BVH, in
// their different orders) must agree on.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "renderer/surface/field_ray.h"

namespace hsb {

inline std::vector<std::uint32_t> span_sources(const FieldRay& tracer) {
  std::vector<std::uint32_t> sources;
  for (const RaySpan& span : tracer.spans) sources.push_back(span.source);
  std::sort(sources.begin(), sources.end());
  return sources;
}

}  // namespace hsb
