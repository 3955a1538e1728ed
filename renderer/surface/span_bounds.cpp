#include "renderer/surface/span_bounds.h"

#include "renderer/surface/instruction_set.h"
#include "renderer/surface/isa_variants.h"

namespace hsb {

void SpanBoundRows::push(const SpanBoundRow& r) {
  if (rows_ == t1.size()) {
    const std::size_t capacity = std::max<std::size_t>(64, 2 * rows_);
    for (std::vector<double>* column : {&t1, &u0, &rate, &tau, &t_near, &t_c, &a, &g_min}) column->resize(capacity);
  }
  const std::size_t k = rows_++;
  t1[k] = r.t1, u0[k] = r.u0, rate[k] = r.rate, tau[k] = r.tau;
  t_near[k] = r.t_near, t_c[k] = r.t_c, a[k] = r.a, g_min[k] = r.g_min;
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
