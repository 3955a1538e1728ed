#pragma once
// Eigen-decomposition of a symmetric tensor, S = V Σ Vᵀ (paper eq. 7).

#include "field/tensor/sym3.h"

namespace hsb {

// Eigenvalues ordered λ1 ≥ λ2 ≥ λ3 (signed: major, medium, minor) and the
// matching unit eigenvectors as the columns of `vectors`. The columns are
// orthonormal and right-handed (det = +1) even when eigenvalues repeat, in
// which case any orthonormal basis of the eigenspace is returned. The sign
// of each eigenvector is arbitrary.
struct Eigensystem {
  Vec3 values = Vec3::Zero();
  Mat3 vectors = Mat3::Identity();
};

Eigensystem decompose(const Sym3& s);

// decompose(s).values alone, the same bits, without the vectors: the same
// iterations on the same tridiagonal matrix, without accumulating the
// rotations (about half the work, where only eigenvalues are asked for:
// every node of a data set, for the colour bar's data extremes).
Vec3 eigenvalues(const Sym3& s);

}  // namespace hsb
