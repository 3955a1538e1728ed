#pragma once
// A colour: three floats, scene-linear RGB unless a name says otherwise.

#include <array>

namespace hsb {

using Rgb = std::array<float, 3>;

}  // namespace hsb
