#pragma once
// Upper bounds of many spans' kernel values at once: the glyph-shape
// tracer's proofs (shape_trace.cpp) sum one per span for every length they
// try, tens of spans a try on a ray through a crowd. Each row holds what
// the tracer knows of one span over [from, s]:
//  - u ≥ max(u0 + rate (to − tau), u_floor), to = min(s, t1): its last
//    tangent, or the most u can fall from its edge (rate 0 where it only
//    rises from from), and the floor a signed glyph's points give it
//    (0 for other glyphs);
//  - g ≥ a (min(t_near, to) − t_c)² + g_min, t_near = max(t_c, from): the
//    span's lower bound of g (RaySpan::lower_a: the bounding ellipsoid's
//    g_e, or its box's or cylinder's) where the ray comes nearest its
//    vertex;
// so K(max(u², that)) bounds its value over [from, s]. One span
// alone (FieldRay::term_bound) and many in SIMD lanes of the active
// instruction set (span_bounds) get the same bits.

#include <algorithm>
#include <cstddef>
#include <vector>

#include "renderer/surface/kernel.h"

namespace hsb {

struct SpanBoundRow {
  double t1, u0, rate, tau, t_near, t_c, a, g_min, u_floor;
};

// The lower bound of g over [from, s], and the upper bound of K it gives.
inline double span_bound_g(const SpanBoundRow& r, double s) {
  const double to = std::min(s, r.t1);
  const double u = std::max(r.u0 + r.rate * (to - r.tau), r.u_floor);
  const double near = std::min(r.t_near, to) - r.t_c;
  return std::max(u * u, r.a * near * near + r.g_min);
}
inline double span_bound(const SpanBoundRow& r, double s, KernelKind kernel) {
  return kernel_value(kernel, span_bound_g(r, s));
}

// Rows side by side, a column each, for the SIMD loop: one buffer, column
// j at j × capacity, so a row is written with one pointer. It only grows:
// clear() keeps it for the next proof, and a row is written in place.
class SpanBoundRows {
 public:
  static constexpr std::size_t kColumns = 9;
  void clear() { rows_ = 0; }
  std::size_t size() const { return rows_; }
  void push(const SpanBoundRow& r) {
    if (rows_ == capacity_) grow();
    double* p = data_.data() + rows_++;
    const std::size_t c = capacity_;
    p[0] = r.t1, p[c] = r.u0, p[2 * c] = r.rate, p[3 * c] = r.tau;
    p[4 * c] = r.t_near, p[5 * c] = r.t_c, p[6 * c] = r.a, p[7 * c] = r.g_min, p[8 * c] = r.u_floor;
  }
  SpanBoundRow row(std::size_t k) const {
    const double* p = data_.data() + k;
    const std::size_t c = capacity_;
    return {p[0], p[c], p[2 * c], p[3 * c], p[4 * c], p[5 * c], p[6 * c], p[7 * c], p[8 * c]};
  }

 private:
  void grow();
  std::vector<double> data_;
  std::size_t capacity_ = 0;
  std::size_t rows_ = 0;
};

// The sum over rows [0, count) of each row's bound of K over [from, s]:
// the proofs' bound of F. Summed in kSumLanes running sums, row k into
// sum k mod kSumLanes, then the sums pairwise ((0+1)+(2+3))+((4+5)+(6+7)),
// the same order under every instruction set, so the same bits; one
// running sum chained each row's addition to the one before, and the
// chain, not the bounds, set the loop's pace.
constexpr std::size_t kSumLanes = 8;
double span_bounds_sum(const SpanBoundRows& rows, std::size_t count, double s, KernelKind kernel);

}  // namespace hsb
