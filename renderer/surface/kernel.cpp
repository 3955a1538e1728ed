#include "renderer/surface/kernel.h"

namespace hsb {

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

const char* kernel_name(KernelKind kind) {
  switch (kind) {
    case KernelKind::wyvill: return "wyvill";
    case KernelKind::quartic: return "quartic";
    case KernelKind::blinn: return "blinn";
  }
  return "?";
}

}  // namespace hsb
