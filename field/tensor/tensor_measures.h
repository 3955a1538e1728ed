#pragma once
// Scalar measures of a symmetric tensor from its eigenvalues, the ones a
// diffusion study reads its data by (and that describe any tensor's shape):
//  - fractional anisotropy (Basser and Pierpaoli 1996),
//      FA = √(3/2) |D − (tr D/3) I| / |D|, in [0, 1] for a positive
//    semi-definite tensor: 0 for a sphere, 1 for a line;
//  - the trace λ1 + λ2 + λ3 (mean diffusivity is a third of it: the
//    colour scalar "mean");
//  - Westin's linear, planar and spherical measures (Westin et al. 2002),
//    of the magnitudes |λ| sorted μ1 ≥ μ2 ≥ μ3, the glyph's radii before
//    scaling: c_l = (μ1 − μ2)/Σμ, c_p = 2(μ2 − μ3)/Σμ, c_s = 3μ3/Σμ, each
//    in [0, 1] and summing to 1 (for diffusion tensors the eigenvalues
//    themselves; for stress the shape its glyph is drawn with);
//  - the mode (Kindlmann's, of the deviatoric part D̃ = D − (tr D/3) I),
//      mode = 3√6 det(D̃/|D̃|) ∈ [−1, 1]: −1 planar (two equal larger
//    eigenvalues), 0 orthotropic, +1 linear (one larger eigenvalue); for
//    stress, the Lode parameter's state: 1 uniaxial tension, −1 uniaxial
//    compression.
// An isotropic tensor has no anisotropy or mode (both are 0), and a zero
// tensor no shape (c_s = 1, a sphere, as the glyph is drawn).

#include "base/vec3.h"
#include "field/tensor/sym3.h"

namespace hsb {

struct WestinMeasures {
  double linear = 0.0, planar = 0.0, spherical = 1.0;
};

double fractional_anisotropy(const Vec3& eigenvalues);
// The same from the tensor's components, without decomposing it (both
// norms are invariant): within round-off (1e-14) of the eigenvalues' FA.
double fractional_anisotropy(const Sym3& tensor);
double tensor_mode(const Vec3& eigenvalues);
WestinMeasures westin_measures(const Vec3& eigenvalues);

}  // namespace hsb
