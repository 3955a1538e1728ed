#pragma once
// Diffusion tensors as a fit leaves them. Noise gives some voxels a tensor
// with a negative eigenvalue, which no diffusion has, and a fit without a
// brain mask fills the background with noise tensors, most of them
// indefinite and the rest scattered among them. A diffusion tool reads
// such voxels as no data; so does hsb, once the tensors are known to be
// diffusion (field/data_quantity.h), so that noise never draws minor
// lines across the bundles nor glyphs over the background.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "field/tensor/sym3.h"

namespace hsb {

struct NoiseLeftOut {
  std::size_t with_data = 0;   // tensors that held data before
  std::size_t indefinite = 0;  // left out: not positive definite
  std::size_t speckle = 0;     // left out: positive definite, but alone among no data
};

// Whether `t` is positive definite (Sylvester's criterion: its leading
// principal minors are positive), without decomposing it.
bool positive_definite(const Sym3& t);

// Sets to NaN (no data) every tensor holding data that is not positive
// definite; then, on a grid (`dims`: nodes along x, y, z, x fastest; null
// for other data) and only where some were indefinite, every node that
// holds data while fewer than kSpeckleNeighbours of its 26 neighbours do:
// the background's noise that happened to be definite. Inside a brain
// nearly all neighbours hold data, and a face of the mask keeps 17 of 26.
NoiseLeftOut leave_out_noise(std::vector<Sym3>& tensors, const std::array<int, 3>* dims);
constexpr int kSpeckleNeighbours = 9;

// The warning for what was left out ("" when nothing was), naming the
// file and the key that reads the tensors as stress instead.
std::string noise_warning(const std::string& path, const NoiseLeftOut& out);

}  // namespace hsb
