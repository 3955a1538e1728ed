#include "renderer/surface/span_bounds.h"

#include "renderer/surface/instruction_set.h"
#include "renderer/surface/isa_variants.h"

namespace hsb {

void SpanBoundRows::grow() {
  const std::size_t capacity = std::max<std::size_t>(64, 2 * capacity_);
  std::vector<double> data(kColumns * capacity);
  for (std::size_t j = 0; j < kColumns; ++j)
    std::copy_n(data_.data() + j * capacity_, rows_, data.data() + j * capacity);
  data_.swap(data);
  capacity_ = capacity;
}

namespace {

// The kernel fixed for the whole loop, its switch out of it: the
// polynomial kernels' loops vectorise (Blinn's exponential runs one at a
// time). Whole groups of kSumLanes rows, then the rest into the first sums.
template <KernelKind kKernel>
[[gnu::always_inline]] inline double sum_loop(const SpanBoundRows& r, std::size_t count, double s) {
  double sums[kSumLanes] = {};
  std::size_t k = 0;
  for (; k + kSumLanes <= count; k += kSumLanes)
    for (std::size_t j = 0; j < kSumLanes; ++j) sums[j] += span_bound(r.row(k + j), s, kKernel);
  for (std::size_t j = 0; k + j < count; ++j) sums[j] += span_bound(r.row(k + j), s, kKernel);
  return ((sums[0] + sums[1]) + (sums[2] + sums[3])) + ((sums[4] + sums[5]) + (sums[6] + sums[7]));
}

#define HSB_BOUNDS_KERNEL(suffix, target_isa)                                                                \
  __attribute__((target(target_isa))) double bounds_##suffix(const SpanBoundRows& rows, std::size_t count,   \
                                                             double s, KernelKind kernel) {                  \
    switch (kernel) {                                                                                        \
      case KernelKind::wyvill: return sum_loop<KernelKind::wyvill>(rows, count, s);                          \
      case KernelKind::quartic: return sum_loop<KernelKind::quartic>(rows, count, s);                        \
      case KernelKind::blinn: return sum_loop<KernelKind::blinn>(rows, count, s);                            \
    }                                                                                                        \
    return 0.0;                                                                                              \
  }
HSB_FOR_EACH_ISA(HSB_BOUNDS_KERNEL)
#undef HSB_BOUNDS_KERNEL

// In InstructionSet order.
constexpr double (*kBounds[])(const SpanBoundRows&, std::size_t, double, KernelKind) = {
    bounds_sse2, bounds_sse42, bounds_avx, bounds_avx2, bounds_avx512};

}  // namespace

double span_bounds_sum(const SpanBoundRows& rows, std::size_t count, double s, KernelKind kernel) {
  return kBounds[std::size_t(active_isa())](rows, count, s, kernel);
}

}  // namespace hsb
