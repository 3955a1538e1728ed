#pragma once
// How eigenvalues become glyph radii and a colour scalar (paper §5).

#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "field/tensor/eigensystem.h"

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
  // A glyph whose largest radius exceeds `ceiling` is scaled down as a whole,
  // so it keeps its shape (a point load's singular neighbourhood would
  // otherwise give glyphs larger than the domain). Then each radius is
  // raised to at least `floor`, so no glyph is flat.
  double floor = 1e-3;
  double ceiling = std::numeric_limits<double>::infinity();
};

// The scalar that colours a glyph: of a tensor's eigenvalues; a flow's
// speed; a scalar array of the data file, sampled at the glyph's centre;
// the position along a curve (0 at its start, 1 at its end).
// family_eigenvalue: each line's own family's (λ1 on major lines, λ3 on
// minor ones), for several families in one picture.
// none: one neutral colour for every glyph, and no colour bar (a picture
// whose shapes carry the meaning, or one printed in grey).
// The tensor measures (tensor_measures.h): fa, trace, westin_linear,
// westin_planar, westin_spherical, mode. direction: not a scalar but the
// major eigenvector's colour (renderer/image/direction_key.h), weighted by
// FA, which is its scalar.
enum class ColorScalar {
  lambda1, lambda2, lambda3, mean, von_mises, family_eigenvalue,
  fa, trace, westin_linear, westin_planar, westin_spherical, mode, direction,
  speed, array, arc_length, none
};

// Radii r_1, r_2, r_3 for eigenvalues λ1 ≥ λ2 ≥ λ3.
Vec3 map_radii(const Vec3& eigenvalues, const GlyphMapping& mapping);

// The name a scene file gives `which` ("lambda3", "speed"; "array" is
// written "array:NAME" there).
const char* color_scalar_name(ColorScalar which);

// The colour scalars a scene names by color_scalar_name() (every one but
// `array`), in the order the scene keys list them.
const std::vector<ColorScalar>& named_color_scalars();

// Whether `which` follows from a tensor's eigenvalues (a flow has none).
bool needs_tensors(ColorScalar which);
// Whether `which` is one value of the tensor wherever it is sampled, as a
// region's measure must be (family_eigenvalue depends on the line, and
// direction is a colour).
inline bool is_tensor_measure(ColorScalar which) {
  return needs_tensors(which) && which != ColorScalar::family_eigenvalue && which != ColorScalar::direction;
}

// The range a bounded measure always spans, [0, 1] for FA and Westin's,
// [−1, 1] for the mode; none for the rest. Its colour bar spans it whatever
// the data holds, so that pictures of different data compare.
std::optional<std::array<double, 2>> natural_range(ColorScalar which);

// The scalars that follow from the eigenvalues (a flow source's are its
// speed three times); 0 for array and arc_length, which the caller sets.
double color_scalar(const Vec3& eigenvalues, ColorScalar which);

}  // namespace hsb
