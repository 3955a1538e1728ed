#pragma once
// The published colormaps as data: each table copied number for number
// from its source (named in `source`), so it can be tested against it.

#include <array>
#include <vector>

namespace hsb {

// One published colormap: its control points, evenly spaced over [0, 1],
// display sRGB in [0, 1], low end first; and whether it is diverging.
struct ColormapTable {
  const char* name;
  std::vector<std::array<float, 3>> colors;
  bool diverging;
  const char* source;  // where the numbers come from, for the reference
};

// Every published table, viridis first.
const std::vector<ColormapTable>& colormap_tables();

}  // namespace hsb
