#include "field/data_quantity.h"

#include <algorithm>
#include <cstddef>

#include "field/tensor/eigensystem.h"

namespace hsb {

DataQuantity recognised_quantity(const std::vector<Vec3>& eigenvalues, bool scan) {
  std::vector<double> mean, flatness;
  std::size_t with_data = 0;
  for (const Vec3& l : eigenvalues) {
    // Zero: outside a diffusion volume's brain mask, where tools write 0.
    if (!l.allFinite() || l.isZero(0.0)) continue;
    ++with_data;
    // Noise's indefinite tensors say nothing of the tissue.
    if (!(l(2) > 0.0)) continue;
    mean.push_back(l.sum() / 3.0);
    flatness.push_back(l(2) / l(0));
  }
  const auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const double definite = scan ? 0.2 : 0.9;
  if (mean.empty() || double(mean.size()) < definite * double(with_data) || median(flatness) < 0.05)
    return DataQuantity::stress;
  const double diffusivity = median(mean);
  const auto within = [&](double lo, double hi) { return diffusivity >= lo && diffusivity <= hi; };
  return within(1e-4, 1e-2) || within(1e-10, 1e-8) || within(0.1, 10.0) ? DataQuantity::diffusion
                                                                         : DataQuantity::stress;
}

DataQuantity recognised_quantity(const std::vector<Sym3>& tensors, bool scan) {
  constexpr std::size_t most = 1 << 15;
  // Strided over the tensors that hold data, so that a brain in a large
  // empty volume is still sampled as densely.
  std::vector<std::size_t> held;
  for (std::size_t i = 0; i < tensors.size(); ++i)
    if (tensors[i].holds_data()) held.push_back(i);
  const std::size_t stride = std::max<std::size_t>(1, (held.size() + most - 1) / most);
  std::vector<Vec3> sampled;
  sampled.reserve(held.size() / stride + 1);
  for (std::size_t i = 0; i < held.size(); i += stride) sampled.push_back(eigenvalues(tensors[held[i]]));
  return recognised_quantity(sampled, scan);
}

}  // namespace hsb
