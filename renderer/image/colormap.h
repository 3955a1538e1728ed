#pragma once
// Colormaps for the glyphs' colour scalar. Tables are in display sRGB, as
// published; they are converted to scene-linear through OCIO before shading.

#include <limits>
#include <optional>
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

// The sRGB colour every glyph gets with glyphs.color_by = "none", and
// direction colour's where there is no direction: a middle grey, dark
// enough to stand out from a white background and a light shell, light
// enough for shading to model it.
inline constexpr Rgb kUncoloured{0.62f, 0.62f, 0.62f};

// A value range mapped onto a colormap, linearly or by the logarithm.
struct ColorScale {
  const Colormap* map = nullptr;
  double lo = 0.0, hi = 1.0;  // with `log`, 0 < lo < hi
  bool log = false;
  // The values' true extremes (NaN: not known). Beyond [lo, hi] they are
  // clipped, and the colour bar says so.
  double data_lo = std::numeric_limits<double>::quiet_NaN();
  double data_hi = std::numeric_limits<double>::quiet_NaN();

  bool clipped_low() const { return data_lo < lo; }
  bool clipped_high() const { return data_hi > hi; }

  // Where `value` lies in the range, 0 at lo and 1 at hi (not clamped;
  // with `log`, values ≤ 0 are at lo). A diverging map over a range
  // across zero is centred on zero (centred_on_zero): each half of the
  // range is spread over its half of the map, so the neutral colour is
  // zero stress and tension and compression of different sizes both
  // reach their full colour.
  double normalized(double value) const;
  bool centred_on_zero() const;
  // Centred on zero with sides of different sizes: the two halves have
  // scales (and ticks) of their own.
  bool two_sided() const { return centred_on_zero() && lo != -hi; }
  Rgb srgb(double value) const { return map->at(normalized(value)); }
};

// The automatic range for `values`: their extremes, unless an extreme is
// an outlier. With qN the Nth percentile and the bulk's extent
// b = max(|q2|, |q98|, q98 − q2) (its reach from zero, or its width), the
// high end is min(max, q98 + 3b) and the low end max(min, q2 − 3b). A
// stress concentration (a hole's 3σ, a notch's 5σ among values near σ:
// within 4 times the bulk's reach) keeps its colour; a singular point's
// extreme values (a point load's own neighbourhood, growing without
// bound) lie beyond the fence and are clipped, so they do not flatten
// every other colour, and the bar marks the clipping (data_lo, data_hi).
// `symmetric` (signed stress, where zero should look neutral): [−m, m],
// with m the same fence over |v|; unless the fence over the positive
// values and the one over the negative values' magnitudes differ more than
// kSidesApart times (a disc's +25 MPa of splitting tension beside
// −970 MPa under its loads): then each side's own, [−m₋, m₊], centred on
// zero, where one m for both left the smaller side too pale to read. `log`: the same over log10 of the
// positive values. A degenerate range is widened so normalized() stays
// finite.
ColorScale auto_scale(const Colormap& map, const std::vector<double>& values, bool symmetric, bool log);
constexpr double kSidesApart = 3.0;

// The map named, else the automatic one for `values`: "coolwarm",
// centred on zero, for values of both signs (both_signs), "viridis" for
// one-signed values or a log scale.
const Colormap& colormap_for(const std::optional<std::string>& name, const std::vector<double>& values, bool log);

// The extremes of `values` (finite ones; positive ones for `log`) into
// scale.data_lo and data_hi.
void record_extremes(ColorScale& scale, const std::vector<double>& values);

// Whether `values` have both signs, each beyond a hundredth of the
// largest magnitude: signed stress, tension and compression, which a
// diverging map centred on zero shows apart.
bool both_signs(const std::vector<double>& values);

}  // namespace hsb
