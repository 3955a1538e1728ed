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
// time).
template <KernelKind kKernel>
[[gnu::always_inline]] inline void bounds_loop(const SpanBoundRows& r, std::size_t count, double s,
                                               double* __restrict out) {
  for (std::size_t k = 0; k < count; ++k) out[k] = span_bound(r.row(k), s, kKernel);
}

#define HSB_BOUNDS_KERNEL(suffix, target_isa)                                                                \
  __attribute__((target(target_isa))) void bounds_##suffix(const SpanBoundRows& rows, std::size_t count,     \
                                                           double s, KernelKind kernel, double* out) {       \
    switch (kernel) {                                                                                        \
      case KernelKind::wyvill: return bounds_loop<KernelKind::wyvill>(rows, count, s, out);                  \
      case KernelKind::quartic: return bounds_loop<KernelKind::quartic>(rows, count, s, out);                \
      case KernelKind::blinn: return bounds_loop<KernelKind::blinn>(rows, count, s, out);                    \
    }                                                                                                        \
  }
HSB_FOR_EACH_ISA(HSB_BOUNDS_KERNEL)
#undef HSB_BOUNDS_KERNEL

// In InstructionSet order.
constexpr void (*kBounds[])(const SpanBoundRows&, std::size_t, double, KernelKind, double*) = {
    bounds_sse2, bounds_sse42, bounds_avx, bounds_avx2, bounds_avx512};

}  // namespace

void span_bounds(const SpanBoundRows& rows, std::size_t count, double s, KernelKind kernel, double* out) {
  kBounds[std::size_t(active_isa())](rows, count, s, kernel, out);
}

}  // namespace hsb
