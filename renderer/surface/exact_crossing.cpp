// The exact first crossing of F = C (FieldRay::exact_crossing).
//
// Along a ray each source's squared distance is a quadratic, g(t), and the
// `wyvill` and `quartic` kernels are polynomials in g (degree 3 and 2), so
// between consecutive support endpoints F(t) − C is one polynomial of degree
// 6 or 4. On each such segment, in ray order, the polynomial is written in
// the Bernstein basis over the segment and subdivided: a piece whose
// coefficients all have one sign holds no root (the variation-diminishing
// property), one with exactly one sign change holds exactly one root, which
// a bracketing method then finds to double precision.

#include <algorithm>
#include <array>
#include <cmath>

#include "renderer/surface/field_ray.h"
#include "renderer/surface/ray_polynomial.h"
#include "renderer/surface/single_source.h"

namespace hsb {
namespace {

// de Casteljau at ½: the two halves' coefficients.
void split_in_half(const RayPolynomial& b, int n, RayPolynomial& left, RayPolynomial& right) {
  RayPolynomial w = b;
  left[0] = w[0];
  right[std::size_t(n)] = w[std::size_t(n)];
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i) w[std::size_t(i)] = 0.5 * (w[std::size_t(i)] + w[std::size_t(i + 1)]);
    left[std::size_t(r)] = w[0];
    right[std::size_t(n - r)] = w[std::size_t(n - r)];
  }
}

int sign_changes(const RayPolynomial& b, int n) {
  int changes = 0;
  bool inside = b[0] >= 0.0;  // F ≥ C counts as inside
  for (int i = 1; i <= n; ++i) {
    const bool here = b[std::size_t(i)] >= 0.0;
    changes += here != inside;
    inside = here;
  }
  return changes;
}

// The root of p in [0, 1] given p(0) = f_lo < 0 ≤ p(1) = f_hi: Newton's
// method from the secant's point, each step kept inside the bracket (one
// that leaves it bisects instead), until the bracket is within
// `tolerance` or p at its upper end within `f_tolerance` of 0. Newton
// nears a root from one side; once its step is below the tolerance, a
// point just past the root closes the bracket from the other. Returns the
// bracket's upper end, where p ≥ 0. Four or five values of p and p' where
// Illinois took seven or eight values, each after a division that the
// next depends on.
double bracketed_newton(const RayPolynomial& p, int n, double f_lo, double f_hi, double tolerance,
                        double f_tolerance, TraceStats& stats) {
  double lo = 0.0, hi = 1.0;
  double x = f_lo / (f_lo - f_hi);
  for (int i = 0; i < 60 && hi - lo > tolerance && f_hi > f_tolerance; ++i) {
    double slope;
    const double value = power_value(p, n, x, slope);
    ++stats.field_evaluations;
    if (value >= 0.0)
      hi = x, f_hi = value;
    else
      lo = x;
    const double step = -value / slope;
    double next = x + step;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    else if (std::fabs(step) < 0.5 * tolerance) next = std::clamp(next + std::copysign(0.25 * tolerance, step), lo, hi);
    x = next;
  }
  return hi;
}

// The first u ∈ [0, 1] where the polynomial goes from < 0 to ≥ 0, or −1.
double first_entry(const RayPolynomial& bernstein, int n, TraceStats& stats) {
  struct Piece {
    RayPolynomial b;
    double lo, hi;
  };
  std::array<Piece, 128> stack;  // depth-first, left halves first
  int top = 0;
  stack[top++] = {bernstein, 0.0, 1.0};
  while (top > 0) {
    const Piece piece = stack[--top];
    const RayPolynomial& b = piece.b;
    const int changes = sign_changes(b, n);
    if (changes == 0) continue;        // one sign throughout: no root
    if (b[0] >= 0.0) return piece.lo;  // starts inside
    const bool ends_inside = b[std::size_t(n)] >= 0.0;
    if ((changes == 1 && ends_inside) || piece.hi - piece.lo < 1e-14 || top + 2 > int(stack.size())) {
      if (!ends_inside) continue;  // an even number of crossings too close to tell apart: a touch
      // Exactly one root in (lo, hi), to 1e-13 of the segment (far below
      // the 1e-5 of the scene asked for) or until F − C is at round-off
      // level. In powers of u a value is n steps of Horner's rule, where
      // de Casteljau's takes n(n + 1)/2 (most segments hold their root in
      // the first piece, and this is where they spend their time); on a
      // piece whose Bernstein coefficients are of order one the power
      // coefficients are at most 2ⁿ larger, a rounding far below the
      // tolerance.
      const double u = bracketed_newton(from_bernstein(b, n), n, b[0], b[std::size_t(n)],
                                        1e-13 / (piece.hi - piece.lo), 1e-15, stats);
      return piece.lo + u * (piece.hi - piece.lo);
    }
    Piece left{{}, piece.lo, 0.5 * (piece.lo + piece.hi)}, right{{}, left.hi, piece.hi};
    split_in_half(b, n, left.b, right.b);
    stack[top++] = right;
    stack[top++] = left;
  }
  return -1.0;
}

// A running sum whose rounding is below this fraction of C stands in for
// F: the crossing it gives is off by that over F's slope, some 1e-10 of a
// glyph, where a pixel is 1e-3 of one.
constexpr double kRunningSumTolerance = 1e-10;

}  // namespace

bool exact_crossing_supported(KernelKind kernel, Blend blend, GlyphShape shape) {
  return shape_is_quadric(shape) && (blend == Blend::max || kernel_traits(kernel).exact);
}

double FieldRay::exact_crossing(const BlobField& field, double tmin, double tmax, bool ends_on_surface,
                                TraceStats& stats) {
  // (blend = "max" never gets here: first_crossing() answers it from the
  // single sources alone.)
  const KernelTraits& kernel = kernel_traits(field.kernel);
  const int degree = 2 * kernel.degree_in_g;
  const double c = field.isovalue;
  const double g_level = level_g(field.kernel, c);
  begin_segments(field, tmin, tmax, ends_on_surface);
  double start, end;
  while (next_segment(field, tmax, start, end, stats)) {
    const std::vector<std::uint32_t>& active = sweep_.active();
    if (active.size() == 1) {
      // One source alone: F = C is its own ellipsoid g = g_level.
      ++stats.field_evaluations;
      ++stats.kernel_evaluations;
      const double t = single_source_entry(spans[active[0]], g_level, start, end);
      if (t >= 0.0) return t;
      continue;
    }
    const double h = end - start;
    RayPolynomial bernstein;
    int n = degree;
    if (bound_.bernstein_form(start, end, kRunningSumTolerance * c, bernstein, n)) {
      // The running sum is F to within far less than anything a picture
      // shows: no need to sum the crowd of active sources again.
      for (int i = 0; i <= n; ++i) bernstein[std::size_t(i)] -= c;
    } else {
      // F(start + h u) − C in powers of u ∈ [0, 1]: g(u) = g(start) +
      // 2 a (start − t_c) h u + a h² u², all of order one on the segment.
      RayPolynomial p{};
      p[0] = -c;
      for (std::uint32_t i : active) {
        const RaySpan& s = spans[i];
        add_kernel_along_ray(kernel, s.g(start), 2.0 * s.a * (start - s.t_c) * h, s.a * h * h, 1.0, p);
      }
      stats.kernel_evaluations += active.size();
      bernstein = to_bernstein(p, degree);
    }
    ++stats.field_evaluations;
    const double u = first_entry(bernstein, n, stats);
    if (u >= 0.0) return start + u * h;
  }
  return -1.0;
}

}  // namespace hsb
