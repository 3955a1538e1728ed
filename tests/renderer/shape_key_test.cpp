// The shape key's samples are the signed glyph's own outlines: a point
// (a cone's apex, its flank straight) at every compressive end, a flat or
// round face (flat to second order) at every tension end.

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/image/shape_key.h"

namespace hsb {
namespace {

// How far the outline falls back from its extreme along x (or y) at
// `offset` across, by linear interpolation between outline points: a
// cone's flank falls back in proportion to the offset, a smooth face to
// its square or less.
double fall_back(const ShapeKeyEntry& entry, bool along_x, double offset) {
  const std::size_t a = along_x ? 0 : 1, b = 1 - a;
  double extreme = 0.0;
  for (const auto& p : entry.outline) extreme = std::max(extreme, p[a]);
  // The outline's point at `offset` across on the positive side.
  for (std::size_t i = 0; i < entry.outline.size(); ++i) {
    const auto& p = entry.outline[i];
    const auto& q = entry.outline[(i + 1) % entry.outline.size()];
    if (p[a] <= 0.0 || q[a] <= 0.0) continue;
    const double lo = std::min(p[b], q[b]), hi = std::max(p[b], q[b]);
    if (offset < lo || offset > hi || hi == lo) continue;
    const double t = (offset - p[b]) / (q[b] - p[b]);
    return extreme - (p[a] + t * (q[a] - p[a]));
  }
  ADD_FAILURE() << "no outline point at " << offset;
  return 0.0;
}

TEST(ShapeKey, EachSampleShowsItsSignAtItsEnds) {
  for (double sharpness : {0.0, 3.0}) {
    SCOPED_TRACE(sharpness);
    const std::vector<ShapeKeyEntry> key = signed_shape_key(sharpness);
    ASSERT_EQ(key.size(), 3u);
    EXPECT_EQ(key[0].label, "tension");
    EXPECT_EQ(key[1].label, "compression");
    EXPECT_EQ(key[2].label, "shear");
    for (const ShapeKeyEntry& e : key) {
      ASSERT_EQ(e.outline.size() % 4, 0u);
      double longest = 0.0;
      for (const auto& p : e.outline) longest = std::max({longest, std::fabs(p[0]), std::fabs(p[1])});
      EXPECT_NEAR(longest, 1.0, 1e-9) << e.label;  // in units of the longest half-axis
    }
    // Across the ends of the long axis, 5 % of the length off it: the
    // compression sample's end is a point whose flank has fallen back by
    // the cone's slope (|y|/ (ρ r_y), ρ = 1.5, r_y = 0.5: 0.067); tension's
    // and shear's are faces, back by under a fifth of that.
    EXPECT_NEAR(fall_back(key[1], true, 0.05), 0.05 / 0.75, 0.002);
    EXPECT_LT(fall_back(key[0], true, 0.05), 0.2 * 0.05 / 0.75);
    EXPECT_LT(fall_back(key[2], true, 0.05), 0.2 * 0.05 / 0.75);
    // Across the ends of the second axis: shear is pushed there (a point),
    // tension pulled (a face).
    EXPECT_GT(fall_back(key[2], false, 0.05), 0.5 * 0.05 * 0.75 / 1.5);
    EXPECT_LT(fall_back(key[0], false, 0.05), 0.01);
  }
}

}  // namespace
}  // namespace hsb
