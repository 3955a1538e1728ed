#pragma once
// The range of each eigenvalue over many tensors (hsb info).

#include <cmath>
#include <ostream>

#include "field/tensor/eigensystem.h"

namespace hsb {

struct EigenvalueRange {
  Vec3 lo = Vec3::Constant(INFINITY);
  Vec3 hi = Vec3::Constant(-INFINITY);

  void add(const Sym3& s) {
    const Vec3 values = decompose(s).values;
    lo = lo.cwiseMin(values);
    hi = hi.cwiseMax(values);
  }
};

// One line per eigenvalue: "  λ1 (major)  [lo, hi]".
inline std::ostream& operator<<(std::ostream& out, const EigenvalueRange& r) {
  const char* names[3] = {"λ1 (major) ", "λ2 (medium)", "λ3 (minor) "};
  for (int k = 0; k < 3; ++k) out << "  " << names[k] << " [" << r.lo[k] << ", " << r.hi[k] << "]\n";
  return out;
}

}  // namespace hsb
