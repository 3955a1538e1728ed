#include "renderer/surface/span_bounds.h"

#include "renderer/surface/instruction_set.h"
#include "renderer/surface/isa_variants.h"

namespace hsb {

void SpanBoundRows::grow() {
  // A whole number of kSumLanes groups, which span_bounds_sum reads whole.
  constexpr std::size_t least = 64;
  static_assert(least % kSumLanes == 0);
  const std::size_t capacity = std::max(least, 2 * capacity_);
  std::vector<double> data(kColumns * capacity);
  for (std::size_t j = 0; j < kColumns; ++j)
    std::copy_n(data_.data() + j * capacity_, rows_, data.data() + j * capacity);
  data_.swap(data);
  capacity_ = capacity;
}

namespace {

// The kernel fixed for the whole loop, its switch out of it: the
// polynomial kernels' loops vectorise (Blinn's exponential runs one at a
// time). Whole groups of kSumLanes rows, then the rest into the first
// sums as one more whole group, its lanes past `count` adding +0 (the
// same bits as leaving them out: every bound is ≥ 0): a proof's rows are
// mostly fewer than a group, and taken one at a time the kernel's branch
// at g = 1 was mispredicted where the lanes select (fig17's beads as
// superquadrics, 480², 1 sample: −2.5 % CPU). The buffer's capacity is a
// whole number of groups, so the lanes past `count` read rows it holds.
template <KernelKind kKernel>
[[gnu::always_inline]] inline double sum_loop(const SpanBoundRows& r, std::size_t count, double s) {
  double sums[kSumLanes] = {};
  std::size_t k = 0;
  for (; k + kSumLanes <= count; k += kSumLanes)
    for (std::size_t j = 0; j < kSumLanes; ++j) sums[j] += span_bound(r.row(k + j), s, kKernel);
  if (k < count) {
    const std::size_t rest = count - k;
    for (std::size_t j = 0; j < kSumLanes; ++j) {
      const double b = span_bound(r.row(k + j), s, kKernel);
      sums[j] += j < rest ? b : 0.0;
    }
  }
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
  // Most tries of a proof sum a few rows (2.2 on fig17's beads as
  // superquadrics): those one at a time, without the call of a loop that
  // works out a whole group of lanes, stores its sums and reads them
  // back one by one (it stalled there). The same bits as the lanes: row k
  // into sum k, each sum from +0 (so never −0, and the absent sums' +0
  // changes nothing), added pairwise.
  if (count <= 4) {
    double sums[4] = {};
    for (std::size_t k = 0; k < count; ++k) sums[k] += span_bound(rows.row(k), s, kernel);
    return (sums[0] + sums[1]) + (sums[2] + sums[3]);
  }
  return kBounds[std::size_t(active_isa())](rows, count, s, kernel);
}

}  // namespace hsb
