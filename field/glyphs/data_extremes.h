#pragma once
// The colour scalar's extremes over the data's own values. The glyphs
// stand on lines, and lines seldom reach the surface where a stress
// concentrates (a tube's bore, a hole's edge): a colour bar made from the
// glyphs alone understated a thick cylinder's hoop stress by 15 % without
// a word. The bar marks the data's true extremes beyond its range.

#include <array>
#include <optional>

#include "field/glyphs/glyph_mapping.h"
#include "field/sampling/field.h"

namespace hsb {

// [min, max] of `color` over the tensors `field` holds at its points or
// cells (a mesh's, a grid's): for each line family's eigenvalue, the least
// λ3 and the largest λ1. Zero and non-finite tensors are no data (a
// diffusion volume's background, a body's outside). Nothing for an
// analytic field (its values are wherever it is sampled), for colours not
// made from the tensor, for bounded measures (their bar spans their whole
// range) and where no value counts.
std::optional<std::array<double, 2>> data_color_extremes(const TensorField& field, ColorScalar color);

}  // namespace hsb
