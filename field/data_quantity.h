#pragma once
// What a tensor data set holds: stress (or strain, or any mechanical
// tensor) or diffusion. A diffusion volume is read differently (design of
// the diffusion issue): a neuroscientist looks for where the anisotropy is
// and which way the fibres run, in a brain mostly isotropic; an engineer
// for where the stress concentrates and whether it pulls or pushes. The
// automatic values follow the quantity (glyph_pipeline.cpp).

#include <vector>

#include "base/vec3.h"
#include "field/tensor/sym3.h"

namespace hsb {

enum class DataQuantity { stress, diffusion };

// Recognised from eigenvalues sampled through the data (NaN-free, non-zero
// ones count: diffusion tools write 0 outside the brain's mask) by what
// every diffusion tensor is and a stress seldom is:
//  - positive definite almost everywhere, λ3 > 0 at 90 % of the samples
//    (fitting noise leaves a few voxels indefinite); in a `scan` (a
//    volume the file places in a patient's anatomical space: NIfTI,
//    MRtrix, NRRD with a space) at 20 %, where a fit without a brain mask
//    fills the background with noise tensors, most of them indefinite;
//  - not flat: the median λ3/λ1 of the positive-definite ones at least
//    0.05 (tissue's FA stays below about 0.95; a bar in uniaxial or a
//    plate in biaxial tension, positive semi-definite too, has λ3 = 0);
//  - a mean diffusivity (the median of tr/3 of the positive-definite
//    ones) of water in tissue, 10⁻⁴ to 10⁻² mm²/s, or the same in m²/s
//    (10⁻¹⁰ to 10⁻⁸) or in µm²/ms (0.1 to 10), the units diffusion tools
//    write.
// A body all in triaxial tension at such magnitudes passes too;
// data.quantity says otherwise.
DataQuantity recognised_quantity(const std::vector<Vec3>& eigenvalues, bool scan = false);

// The same over a data set's own tensors (up to 32,768 of them, evenly
// strided, are decomposed).
DataQuantity recognised_quantity(const std::vector<Sym3>& tensors, bool scan);

}  // namespace hsb
