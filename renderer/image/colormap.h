#pragma once
// Colormaps for the glyphs' colour scalar. Tables are in display sRGB, as
// published; they are converted to scene-linear through OCIO before shading.

#include <string>
#include <vector>

#include "renderer/render/shading.h"

namespace hsb {

struct Colormap {
  std::string name;
  std::vector<Rgb> table;  // evenly spaced control points, display sRGB in [0, 1]
  bool diverging = false;  // centred on zero: its default range is symmetric

  // The colour at u ∈ [0, 1] (clamped), linear between control points.
  Rgb at(double u) const;
};

// A published map by name (colormap_tables.h): the sequential "viridis",
// "cividis", "magma", the diverging "coolwarm" (Moreland's) and "RdBu"
// (ColorBrewer's; stress is signed, and zero should look neutral), or any
// of them reversed, "viridis_r". Throws std::invalid_argument for others.
const Colormap& colormap_named(const std::string& name);
const std::vector<std::string>& colormap_names();

// A value range mapped onto a colormap, linearly or by the logarithm.
struct ColorScale {
  const Colormap* map = nullptr;
  double lo = 0.0, hi = 1.0;  // with `log`, 0 < lo < hi
  bool log = false;

  // Where `value` lies in the range, 0 at lo and 1 at hi (not clamped;
  // with `log`, values ≤ 0 are at lo).
  double normalized(double value) const;
  Rgb srgb(double value) const { return map->at(normalized(value)); }
};

// The automatic range for `values`: their 2nd to 98th percentile, or [−m, m]
// with m the 98th percentile of |v| when `symmetric` (signed stress, where
// zero should look neutral); with `log`, the percentiles of the positive
// values. Percentiles rather than extremes because stress fields have
// singular points (a point load's own neighbourhood) whose few extreme
// values would otherwise flatten every other colour; values outside the
// range take the end colours. A degenerate range is widened so
// normalized() stays finite.
ColorScale auto_scale(const Colormap& map, const std::vector<double>& values, bool symmetric, bool log);

}  // namespace hsb
