#pragma once
// Upper bounds of many spans' kernel values at once: the glyph-shape
// tracer's proofs (shape_trace.cpp) sum one per span for every length they
// try, tens of spans a try on a ray through a crowd, and its probes ask
// each live span's bound where they look. What the tracer knows of span i
// over [from, s], from = max(t, t0) (t where the walk stands):
//  - u ≥ u0 + rate (to − tau), to = min(s, t1): its last tangent, or the
//    most u can fall from its edge (rate 0 where the tangent only rises
//    from `from`);
//  - g ≥ g_e ≥ a (min(t_near, to) − t_c)² + g_min, t_near = max(t_c, from):
//    the bounding ellipsoid where the ray is closest to its centre;
// so K(max(max(u, 0)², that)) bounds its value over [from, s]. A span that
// ended before t adds nothing.
//
// The tracer keeps what it knows a column each (SpanColumns), so the bound
// of a run of spans is one loop over them in SIMD lanes, with no row of
// each span built first: building those rows for every proof, span by
// span, cost more than summing them. One span alone (span_bound) and many
// in SIMD lanes of any instruction set give the same bits.

#include <cstddef>

#include "renderer/surface/kernel.h"

namespace hsb {

// Each span of a ray, in the walk's order (the order the ray enters them):
// its interval [t0, t1], its bounding ellipsoid's g_e along the ray,
// a (t − t_c)² + g_min, and `fall`, the most its u falls per unit (Lσ√a,
// glyph_shape.h); then u and du/dt where it was last evaluated, at
// tangent_at (−∞, or anything before t0, when it has not been).
struct SpanColumns {
  const double *t0, *t1, *t_c, *a, *g_min, *fall;
  const double *u, *du_dt, *tangent_at;
};

// Span i's lower bound of g over [max(t, t0), s] (s at least that).
[[gnu::always_inline]] inline double span_bound_g(const SpanColumns& c, std::size_t i, double t, double s) {
  // Every column read first, whatever is chosen below: selects of values
  // already loaded, not branches (a load in only one arm of a select is
  // control flow to the vectoriser), so the loops over spans become SIMD.
  const double t0 = c.t0[i], t1 = c.t1[i], t_c = c.t_c[i], a = c.a[i], g_min = c.g_min[i], fall = c.fall[i];
  const double u_t = c.u[i], du = c.du_dt[i], tangent_at = c.tangent_at[i];
  const double from = t0 > t ? t0 : t;
  const bool tangent = tangent_at >= t0, falling = du < 0.0;
  const double rising_u0 = u_t + du * (from - tangent_at);
  const double u0 = tangent ? (falling ? u_t : rising_u0) : 1.0;
  const double rate = tangent ? (falling ? du : 0.0) : -fall;
  const double tau = tangent ? (falling ? tangent_at : 0.0) : t0;
  const double to = s < t1 ? s : t1;
  const double u_line = u0 + rate * (to - tau);
  const double u = u_line > 0.0 ? u_line : 0.0;
  const double t_near = t_c > from ? t_c : from;
  const double near = (t_near < to ? t_near : to) - t_c;
  const double g_e = a * near * near + g_min;
  const double uu = u * u;
  return uu > g_e ? uu : g_e;
}

// Span i's bound of K over [max(t, t0), s]; 0 for a span that ended
// before t.
[[gnu::always_inline]] inline double span_bound(const SpanColumns& c, std::size_t i, double t, double s,
                                                KernelKind kernel) {
  const double k = kernel_value(kernel, span_bound_g(c, i, t, s));
  return c.t1[i] >= t ? k : 0.0;  // (t1 was read above: no load in an arm)
}

// The sum of span_bound(c, i, t, s) over spans [first, end): the proofs'
// bound of F over [t, s], when [first, end) holds every span live at t
// and every one begun by s. Summed in kSumLanes running sums, the span
// k places past `first` into sum k mod kSumLanes, then the sums pairwise
// ((0+1)+(2+3))+((4+5)+(6+7)), the same order under every instruction set,
// so the same bits; one running sum chained each span's addition to the
// one before, and the chain, not the bounds, set the loop's pace.
constexpr std::size_t kSumLanes = 8;
double span_bounds_sum(const SpanColumns& c, std::size_t first, std::size_t end, double t, double s,
                       KernelKind kernel);

// span_bound(c, i, t, t), each span's bound where the walk stands, into
// out[i − first] for i in [first, end): the probes' bound of each term.
void span_bounds_at(const SpanColumns& c, std::size_t first, std::size_t end, double t, KernelKind kernel,
                    double* out);

}  // namespace hsb
