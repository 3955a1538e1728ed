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
#include "renderer/surface/illinois.h"

namespace hsb {
namespace {

constexpr int max_degree = 6;
using Coefficients = std::array<double, max_degree + 1>;

// K(g) as power coefficients in g.
Coefficients kernel_polynomial(KernelKind kind) {
  switch (kind) {
    case KernelKind::wyvill: return {1.0, detail::wyvill_c, detail::wyvill_b, detail::wyvill_a, 0, 0, 0};
    case KernelKind::quartic: return {1.0, -2.0, 1.0, 0, 0, 0, 0};
    case KernelKind::blinn: break;
  }
  return {};
}

int kernel_degree_in_g(KernelKind kind) { return kind == KernelKind::wyvill ? 3 : 2; }

// Adds k(q(u)) to `p`, with q(u) = q0 + q1 u + q2 u² and k given in g.
void add_composition(const Coefficients& k, int k_degree, double q0, double q1, double q2,
                     Coefficients& p) {
  // Powers of q by repeated multiplication; degree 2·k_degree ≤ 6.
  Coefficients power{1, 0, 0, 0, 0, 0, 0};
  int power_degree = 0;
  p[0] += k[0];
  for (int j = 1; j <= k_degree; ++j) {
    Coefficients next{};
    for (int i = 0; i <= power_degree; ++i) {
      next[std::size_t(i)] += power[std::size_t(i)] * q0;
      next[std::size_t(i + 1)] += power[std::size_t(i)] * q1;
      next[std::size_t(i + 2)] += power[std::size_t(i)] * q2;
    }
    power = next;
    power_degree += 2;
    for (int i = 0; i <= power_degree; ++i) p[std::size_t(i)] += k[std::size_t(j)] * power[std::size_t(i)];
  }
}

double binomial(int n, int k) {
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * double(n - k + i) / double(i);
  return r;
}

// Power coefficients on [0, 1] to Bernstein coefficients of degree n.
Coefficients to_bernstein(const Coefficients& p, int n) {
  Coefficients b{};
  for (int j = 0; j <= n; ++j)
    for (int k = 0; k <= j; ++k) b[std::size_t(j)] += binomial(j, k) / binomial(n, k) * p[std::size_t(k)];
  return b;
}

// de Casteljau at u: the value, and the two halves' coefficients.
double de_casteljau(const Coefficients& b, int n, double u, Coefficients* left, Coefficients* right) {
  Coefficients w = b;
  if (left) (*left)[0] = w[0];
  if (right) (*right)[std::size_t(n)] = w[std::size_t(n)];
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i) w[std::size_t(i)] = (1 - u) * w[std::size_t(i)] + u * w[std::size_t(i + 1)];
    if (left) (*left)[std::size_t(r)] = w[0];
    if (right) (*right)[std::size_t(n - r)] = w[std::size_t(n - r)];
  }
  return w[0];
}

int sign_changes(const Coefficients& b, int n) {
  int changes = 0;
  bool inside = b[0] >= 0.0;  // F ≥ C counts as inside
  for (int i = 1; i <= n; ++i) {
    const bool here = b[std::size_t(i)] >= 0.0;
    changes += here != inside;
    inside = here;
  }
  return changes;
}

// The first u ∈ [0, 1] where the polynomial goes from < 0 to ≥ 0, or −1.
double first_entry(const Coefficients& bernstein, int n, TraceStats& stats) {
  struct Piece {
    Coefficients b;
    double lo, hi;
  };
  std::array<Piece, 128> stack;  // depth-first, left halves first
  int top = 0;
  stack[top++] = {bernstein, 0.0, 1.0};
  while (top > 0) {
    const Piece piece = stack[--top];
    const Coefficients& b = piece.b;
    const int changes = sign_changes(b, n);
    if (changes == 0) continue;        // one sign throughout: no root
    if (b[0] >= 0.0) return piece.lo;  // starts inside
    const bool ends_inside = b[std::size_t(n)] >= 0.0;
    if ((changes == 1 && ends_inside) || piece.hi - piece.lo < 1e-14 || top + 2 > int(stack.size())) {
      if (!ends_inside) continue;  // an even number of crossings too close to tell apart: a touch
      // Exactly one root in (lo, hi): Illinois on the piece's own
      // coefficients, to 1e-13 of the segment (far below the 1e-5 of the
      // scene asked for) or until F − C is at round-off level.
      const double u = illinois(
          [&](double x) {
            ++stats.field_evaluations;
            return de_casteljau(b, n, x, nullptr, nullptr);
          },
          0.0, 1.0, b[0], b[std::size_t(n)], 1e-13 / (piece.hi - piece.lo), 1e-15, 60);
      return piece.lo + u * (piece.hi - piece.lo);
    }
    Piece left{{}, piece.lo, 0.5 * (piece.lo + piece.hi)}, right{{}, left.hi, piece.hi};
    de_casteljau(b, n, 0.5, &left.b, &right.b);
    stack[top++] = right;
    stack[top++] = left;
  }
  return -1.0;
}

// g where an isolated source's K equals C; cached because the bisection
// behind it is too slow to repeat for every ray.
double level_g(KernelKind kind, double isovalue) {
  thread_local KernelKind cached_kind = KernelKind::wyvill;
  thread_local double cached_isovalue = -1.0, cached_g = 0.0;
  if (kind != cached_kind || isovalue != cached_isovalue) {
    const double u = kernel_level_radius(kind, isovalue);
    cached_kind = kind;
    cached_isovalue = isovalue;
    cached_g = u * u;
  }
  return cached_g;
}

// Where the ray enters one source's own level surface g = g_level within
// [lo, hi] (lo itself when it starts inside), or −1.
double single_source_entry(const RaySpan& s, double g_level, double lo, double hi) {
  if (s.g_min >= g_level) return -1.0;
  const double half = std::sqrt((g_level - s.g_min) / s.a);
  if (s.t_c + half < lo) return -1.0;
  const double t = std::max(s.t_c - half, lo);
  return t <= hi ? t : -1.0;
}

}  // namespace

bool exact_crossing_supported(KernelKind kernel, Blend blend) {
  return blend == Blend::max || kernel == KernelKind::wyvill || kernel == KernelKind::quartic;
}

double FieldRay::exact_crossing(const BlobField& field, double tmin, double tmax, TraceStats& stats) {
  if (field.blend == Blend::max) {
    // A union of ellipsoids: each source's own surface is g = g_C, the
    // level where K = C, crossed at a quadratic's root.
    stats.spans += spans.size();
    const double g_level = level_g(field.kernel, field.isovalue);
    double best = -1.0;
    for (const RaySpan& s : spans) {
      const double t = single_source_entry(s, g_level, tmin, tmax);
      if (t >= 0.0 && (best < 0.0 || t < best)) best = t;
    }
    return best;
  }

  const Coefficients k = kernel_polynomial(field.kernel);
  const int k_degree = kernel_degree_in_g(field.kernel);
  const int degree = 2 * k_degree;
  const double c = field.isovalue;
  const double g_level = level_g(field.kernel, c);
  begin_segments(tmin, stats);
  double start, end;
  while (next_segment(tmax, start, end)) {
    if (active_.size() == 1) {
      // One source alone: F = C is its own ellipsoid g = g_level.
      ++stats.field_evaluations;
      ++stats.kernel_evaluations;
      const double t = single_source_entry(spans[active_[0]], g_level, start, end);
      if (t >= 0.0) return t;
      continue;
    }
    const double h = end - start;
    // Skip a segment whose largest possible F cannot reach C: each source
    // peaks where g is smallest on the segment.
    double bound = 0.0;
    for (std::uint32_t i : active_) {
      const RaySpan& s = spans[i];
      const double t_near = std::clamp(s.t_c, start, end);
      bound += kernel_value(field.kernel, s.g(t_near));
    }
    ++stats.field_evaluations;
    stats.kernel_evaluations += active_.size();
    if (bound < c) continue;

    // F(start + h u) − C in powers of u ∈ [0, 1]: g(u) = g(start) +
    // 2 a (start − t_c) h u + a h² u², all of order one on the segment.
    Coefficients p{};
    p[0] = -c;
    for (std::uint32_t i : active_) {
      const RaySpan& s = spans[i];
      add_composition(k, k_degree, s.g(start), 2.0 * s.a * (start - s.t_c) * h, s.a * h * h, p);
    }
    const double u = first_entry(to_bernstein(p, degree), degree, stats);
    if (u >= 0.0) return start + u * h;
  }
  return -1.0;
}

}  // namespace hsb
