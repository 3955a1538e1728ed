#pragma once
// Each source's place in a space-filling (Morton, Z-order) curve through
// the field's bounds: sources close in rank are close in space. Lists of
// sources kept in rank order fall into compact groups (nearby_sources.h),
// and rank is a canonical order for the spans of a ray that does not depend
// on how they were found.

#include <cstdint>
#include <vector>

#include "base/box3.h"
#include "renderer/surface/blob_field.h"

namespace hsb {

// rank[i] is source i's position along the curve through `bounds`
// (ties by index): a permutation of 0 … n−1.
std::vector<std::uint32_t> spatial_ranks(const BlobField& field, const Box3& bounds);

}  // namespace hsb
