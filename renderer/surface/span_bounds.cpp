#include "renderer/surface/span_bounds.h"

#include "renderer/surface/instruction_set.h"
#include "renderer/surface/isa_variants.h"

namespace hsb {

namespace {

// The kernel fixed for the whole loop, its switch out of it: the
// polynomial kernels' loops vectorise (Blinn's exponential runs one at a
// time). Whole groups of kSumLanes spans, then the rest into the first sums.
template <KernelKind kKernel>
[[gnu::always_inline]] inline double sum_loop(const SpanColumns& c, std::size_t first, std::size_t end, double t,
                                              double s) {
  double sums[kSumLanes] = {};
  std::size_t i = first;
  for (; i + kSumLanes <= end; i += kSumLanes)
    for (std::size_t j = 0; j < kSumLanes; ++j) sums[j] += span_bound(c, i + j, t, s, kKernel);
  for (std::size_t j = 0; i + j < end; ++j) sums[j] += span_bound(c, i + j, t, s, kKernel);
  return ((sums[0] + sums[1]) + (sums[2] + sums[3])) + ((sums[4] + sums[5]) + (sums[6] + sums[7]));
}

template <KernelKind kKernel>
[[gnu::always_inline]] inline void each_loop(const SpanColumns& c, std::size_t first, std::size_t end, double t,
                                             double* out) {
  for (std::size_t i = first; i < end; ++i) out[i - first] = span_bound(c, i, t, t, kKernel);
}

#define HSB_BOUNDS_KERNELS(suffix, target_isa)                                                                  \
  __attribute__((target(target_isa))) double sum_##suffix(const SpanColumns& c, std::size_t first,             \
                                                          std::size_t end, double t, double s, KernelKind kernel) { \
    switch (kernel) {                                                                                           \
      case KernelKind::wyvill: return sum_loop<KernelKind::wyvill>(c, first, end, t, s);                        \
      case KernelKind::quartic: return sum_loop<KernelKind::quartic>(c, first, end, t, s);                      \
      case KernelKind::blinn: return sum_loop<KernelKind::blinn>(c, first, end, t, s);                          \
    }                                                                                                           \
    return 0.0;                                                                                                 \
  }                                                                                                             \
  __attribute__((target(target_isa))) void each_##suffix(const SpanColumns& c, std::size_t first,              \
                                                         std::size_t end, double t, KernelKind kernel,          \
                                                         double* out) {                                         \
    switch (kernel) {                                                                                           \
      case KernelKind::wyvill: return each_loop<KernelKind::wyvill>(c, first, end, t, out);                     \
      case KernelKind::quartic: return each_loop<KernelKind::quartic>(c, first, end, t, out);                   \
      case KernelKind::blinn: return each_loop<KernelKind::blinn>(c, first, end, t, out);                       \
    }                                                                                                           \
  }
HSB_FOR_EACH_ISA(HSB_BOUNDS_KERNELS)
#undef HSB_BOUNDS_KERNELS

// In InstructionSet order.
constexpr double (*kSums[])(const SpanColumns&, std::size_t, std::size_t, double, double, KernelKind) = {
    sum_sse2, sum_sse42, sum_avx, sum_avx2, sum_avx512};
constexpr void (*kEach[])(const SpanColumns&, std::size_t, std::size_t, double, KernelKind, double*) = {
    each_sse2, each_sse42, each_avx, each_avx2, each_avx512};

}  // namespace

double span_bounds_sum(const SpanColumns& c, std::size_t first, std::size_t end, double t, double s,
                       KernelKind kernel) {
  return kSums[std::size_t(active_isa())](c, first, end, t, s, kernel);
}

void span_bounds_at(const SpanColumns& c, std::size_t first, std::size_t end, double t, KernelKind kernel,
                    double* out) {
  kEach[std::size_t(active_isa())](c, first, end, t, kernel, out);
}

}  // namespace hsb
