#include "renderer/surface/kernel.h"

#include <stdexcept>

namespace hsb {
namespace {

// Blinn's kernel is no polynomial; this cubic lies above it on g ∈ [0, 1] by
// at most 0.009: a least-squares fit at Chebyshev nodes, raised by its
// largest shortfall (0.0045, at g = 0) plus 1e-5 to cover what dense sampling cannot
// see (kernel_test checks P ≥ K at 10⁶ points).
constexpr std::array<double, 4> blinn_upper_bound{1.00001, -2.514584397344672, 2.3726943626276973,
                                                  -0.8571366186108049};

const std::array<KernelTraits, 3> traits{{
    {KernelKind::wyvill, "wyvill", 1.5834297477401706,  // at u ≈ 0.50347, where d²K/du² = 0
     3, {1.0, detail::wyvill_c, detail::wyvill_b, detail::wyvill_a}, true},
    {KernelKind::quartic, "quartic", 1.5396007178390020,  // 8 / (3√3), at u = 1/√3
     2, {1.0, -2.0, 1.0, 0.0}, true},
    {KernelKind::blinn, "blinn", 1.4674055850147556,  // √(2s)·e^(−½)/(1 − e^(−s)), at u = 1/√(2s)
     3, blinn_upper_bound, false},
}};

}  // namespace

const KernelTraits& kernel_traits(KernelKind kind) {
  for (const KernelTraits& t : traits)
    if (t.kind == kind) return t;
  throw std::invalid_argument("unknown kernel");
}

const std::array<KernelTraits, 3>& all_kernel_traits() { return traits; }

double kernel_level_radius(KernelKind kind, double isovalue) {
  // K decreases monotonically in g on [0, 1] for every kernel, so bisection
  // on g finds the unique level; 100 halvings reach double precision.
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (kernel_value(kind, mid) > isovalue ? lo : hi) = mid;
  }
  return std::sqrt(0.5 * (lo + hi));
}

}  // namespace hsb
