#include "field/data_quantity.h"

#include <algorithm>
#include <cstddef>

namespace hsb {

DataQuantity recognised_quantity(const std::vector<Vec3>& eigenvalues) {
  std::vector<double> mean, flatness;
  std::size_t definite = 0;
  for (const Vec3& l : eigenvalues) {
    // Zero: outside a diffusion volume's brain mask, where tools write 0.
    if (!l.allFinite() || l.isZero(0.0)) continue;
    mean.push_back(l.sum() / 3.0);
    flatness.push_back(l(0) > 0.0 ? l(2) / l(0) : -1.0);
    definite += l(2) > 0.0;
  }
  const auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  if (mean.empty() || double(definite) < 0.9 * double(mean.size()) || median(flatness) < 0.05)
    return DataQuantity::stress;
  const double diffusivity = median(mean);
  const auto within = [&](double lo, double hi) { return diffusivity >= lo && diffusivity <= hi; };
  return within(1e-4, 1e-2) || within(1e-10, 1e-8) || within(0.1, 10.0) ? DataQuantity::diffusion
                                                                         : DataQuantity::stress;
}

}  // namespace hsb
