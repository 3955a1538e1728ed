#pragma once
// How eigenvalues become glyph radii and a colour scalar (paper §5).

#include <limits>

#include "field/eigensystem.h"

namespace hsb {

enum class RadiusMapping {
  linear,      // r_k = s·|λ_k|                         (paper Fig. 5)
  sqrt,        // r_k = s·√|λ_k|                        (paper Fig. 6)
  normalized,  // r_k = s·|λ_k| / max_j |λ_j|: shape kept, size fixed (Fig. 7)
  constant,    // r_k = s: spheres
};

struct GlyphMapping {
  RadiusMapping mapping = RadiusMapping::linear;
  double scale = 1.0;
  // Radii are clamped to [floor, ceiling] so no glyph is flat and the
  // singular neighbourhood of a load cannot produce a glyph larger than the
  // domain.
  double floor = 1e-3;
  double ceiling = std::numeric_limits<double>::infinity();
};

// The scalar that colours a glyph.
enum class ColorScalar { lambda1, lambda2, lambda3, mean, von_mises };

// Radii r_1, r_2, r_3 for eigenvalues λ1 ≥ λ2 ≥ λ3.
Vec3 map_radii(const Vec3& eigenvalues, const GlyphMapping& mapping);

double color_scalar(const Vec3& eigenvalues, ColorScalar which);

}  // namespace hsb
