#pragma once
// The colour scalar's extremes over the data's own values. The glyphs
// stand on lines, and lines seldom reach the surface where a stress
// concentrates (a tube's bore, a hole's edge): a colour bar made from the
// glyphs alone understated a thick cylinder's hoop stress by 15 % without
// a word. The bar marks the data's true extremes beyond its range.

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "field/glyphs/glyph_mapping.h"
#include "field/sampling/field.h"
#include "field/tracing/trajectory.h"

namespace hsb {

// The eigenvalue a line of `family` shows along it: λ1 on a major
// (tension) line, the stress it carries; λ3 on a minor one.
ColorScalar family_eigenvalue(EigenFamily family);

// [min, max] of `color` over the tensors `field` holds at its points or
// cells (a mesh's, a grid's): for each line family's eigenvalue, over the
// eigenvalues of the `families` drawn (λ3's least and λ1's largest for
// both major and minor lines). Zero and non-finite tensors are no data (a
// diffusion volume's background, a body's outside). Nothing for an
// analytic field (its values are wherever it is sampled), for colours not
// made from the tensor, for bounded measures (their bar spans their whole
// range) and where no value counts.
std::optional<std::array<double, 2>> data_color_extremes(
    const TensorField& field, ColorScalar color,
    const std::vector<EigenFamily>& families = {EigenFamily::major, EigenFamily::minor});

// The same scalars at up to `most` of the field's points or cells, evenly
// strided (each drawn family's eigenvalue, for a family's eigenvalue): the
// data's own distribution, which the automatic colour range's fence
// reads, so that a bounded concentration the lines miss (a notch's root)
// is inside the range while a singular point's values stay outliers.
// Empty where data_color_extremes() gives nothing.
std::vector<double> data_color_sample(const TensorField& field, ColorScalar color,
                                      const std::vector<EigenFamily>& families, std::size_t most = 1 << 16);

}  // namespace hsb
