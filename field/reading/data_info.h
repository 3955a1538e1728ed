#pragma once
// A human-readable description of a data set (hsb info).

#include <string>

#include "field/glyph_pipeline.h"

namespace hsb {

// Kind, bounds, cells and their types, arrays, and the range of each
// eigenvalue. For the analytic point load the eigenvalues are taken on a
// 21×21×21 grid of the domain (the load point itself included, where the
// clamped value is reported).
std::string describe_data(const DataSpec& spec);

}  // namespace hsb
