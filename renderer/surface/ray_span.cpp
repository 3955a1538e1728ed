#include "renderer/surface/ray_span.h"

#include "renderer/surface/isa_variants.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

namespace hsb {

namespace {

// One source against one ray, in two stages. The first, with no division
// or root, decides whether the ray's line enters the support at all; a
// lone ray stops there for the many boxes it crosses without meeting their
// ellipsoids. Branch-free, so that the loops below vectorise, over rays or
// over sources.
struct ScaledRay {
  double wp[3], wd[3];  // W (o − c) and W d: the ray q(t) = wp + t wd in the stored frame
  double a;        // |W d|²
  double half_b;   // (W d)·(W (o − c))
  double a_g_min;  // a · g at the closest approach
  double cross[3];  // Wp × Wd: a_g_min is its squared length
  bool line_enters() const { return (a > 0.0) & (a_g_min < a); }  // false for NaN and a = 0
};

[[gnu::always_inline]] inline ScaledRay scaled_ray(const double (&w)[9], double cx, double cy, double cz, double ox, double oy, double oz,
                            double dx, double dy, double dz) {
  // In the source's scaled frame q(t) = W(o − c) + t W d, and g = |q|².
  const double px = ox - cx, py = oy - cy, pz = oz - cz;
  const double wp0 = w[0] * px + w[1] * py + w[2] * pz;
  const double wp1 = w[3] * px + w[4] * py + w[5] * pz;
  const double wp2 = w[6] * px + w[7] * py + w[8] * pz;
  const double wd0 = w[0] * dx + w[1] * dy + w[2] * dz;
  const double wd1 = w[3] * dx + w[4] * dy + w[5] * dz;
  const double wd2 = w[6] * dx + w[7] * dy + w[8] * dz;
  // g(t) = a t² + 2 half_b t + |Wp|², smallest at t_c = −half_b/a, where
  // a·g = |Wp|²|Wd|² − (Wp·Wd)² = |Wp × Wd|² (Lagrange's identity). The
  // cross product keeps it accurate when the camera is far from a small
  // glyph, where |Wp|² − half_b²/a would cancel catastrophically.
  const double x0 = wp1 * wd2 - wp2 * wd1, x1 = wp2 * wd0 - wp0 * wd2, x2 = wp0 * wd1 - wp1 * wd0;
  return {{wp0, wp1, wp2},
          {wd0, wd1, wd2},
          wd0 * wd0 + wd1 * wd1 + wd2 * wd2,
          wd0 * wp0 + wd1 * wp1 + wd2 * wp2,
          x0 * x0 + x1 * x1 + x2 * x2,
          {x0, x1, x2}};
}

// A lower bound of g in vertex form, g ≥ a (t − t_v)² + g_v (RaySpan's
// lower_*).
struct VertexForm {
  double a, t_v, g_v;
};

struct LaneSpan {
  double t0, t1, a, t_c, g_min;
  VertexForm lower;
  bool enters;
};

// The second stage: the support's interval on the ray, clipped to [tmin, tmax].
[[gnu::always_inline]] inline LaneSpan finish_span(const ScaledRay& r, double tmin, double tmax) {
  // One division for three quotients: SIMD division is slow.
  const double inv_a = 1.0 / r.a;
  const double tc = -r.half_b * inv_a;
  const double g_min = r.a_g_min * inv_a;
  const double reach = (1.0 - g_min) * inv_a;  // (half the support's length)²
  const double half_width = std::sqrt(reach > 0.0 ? reach : 0.0);
  const double t0 = tc - half_width > tmin ? tc - half_width : tmin;
  const double t1 = tc + half_width < tmax ? tc + half_width : tmax;
  return {t0, t1, r.a, tc, g_min, {r.a, tc, g_min}, bool(r.line_enters() & (g_min < 1.0) & (t0 < t1))};
}

// A third stage for shapes with a box (ray_span.h): the span narrowed to
// where q(t) is inside |q_k| ≤ box on every axis k. Each slab is centred
// where q_k = 0 and box/|wd_k| wide on either side (one division an axis,
// not two); a ray parallel to a slab is inside it everywhere or nowhere.
// Branch-free, as the stages before. `slabs` gets what each slab says of
// g: u ≥ |q_k|/box (the gauge is at least its largest component,
// glyph_shape.h), so g ≥ (wd_k/box)² (t − centre)², or the constant
// (wp_k/box)² along a ray parallel to the slab.
[[gnu::always_inline]] inline void clip_to_box(const ScaledRay& r, double box, LaneSpan& span, VertexForm (&slabs)[3]) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double inv_box2 = 1.0 / (box * box);
  bool outside = false;
  for (int k = 0; k < 3; ++k) {
    const double inverse = 1.0 / r.wd[k], centre = -r.wp[k] * inverse, reach = box * std::fabs(inverse);
    const bool parallel = r.wd[k] == 0.0;
    slabs[k] = {(r.wd[k] * r.wd[k]) * inv_box2, parallel ? 0.0 : centre,
                parallel ? (r.wp[k] * r.wp[k]) * inv_box2 : 0.0};
    const double lo = parallel ? -inf : centre - reach, hi = parallel ? inf : centre + reach;
    outside |= parallel & (std::fabs(r.wp[k]) > box);
    span.t0 = span.t0 < lo ? lo : span.t0;
    span.t1 = hi < span.t1 ? hi : span.t1;
  }
  span.enters = span.enters & !outside & (span.t0 <= span.t1);
}

// And the span narrowed to the cylinder ‖q_⊥‖ ≤ radius about the symmetry
// axis: g's own quadratic in the two components across it (across[k] = 1
// for those, 0 for the axis's), its closest approach from the axis's
// component of Wp × Wd as g's is from the whole (Lagrange's identity in
// the plane across). A ray along the axis is inside everywhere or nowhere.
// `wall` gets what the cylinder says of g: u ≥ ‖q_⊥‖/radius (glyph_shape.h,
// support_cylinder_radius), so g ≥ that quadratic over radius².
[[gnu::always_inline]] inline void clip_to_cylinder(const ScaledRay& r, double radius, const double (&across)[3], LaneSpan& span,
                             VertexForm& wall) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double a = 0.0, half_b = 0.0, p = 0.0, x = 0.0;
  for (int k = 0; k < 3; ++k) {
    a += across[k] * (r.wd[k] * r.wd[k]);
    half_b += across[k] * (r.wd[k] * r.wp[k]);
    p += across[k] * (r.wp[k] * r.wp[k]);
    x += (1.0 - across[k]) * r.cross[k];
  }
  const double radius2 = radius * radius;
  const bool parallel = a == 0.0;
  const double inv_a = 1.0 / a, tc = -half_b * inv_a, g_min = x * x * inv_a;
  const double reach = (radius2 - g_min) * inv_a;
  const double half_width = std::sqrt(reach > 0.0 ? reach : 0.0);
  const double lo = parallel ? -inf : tc - half_width, hi = parallel ? inf : tc + half_width;
  const double inv_radius2 = 1.0 / radius2;
  wall = {a * inv_radius2, parallel ? 0.0 : tc, (parallel ? p : g_min) * inv_radius2};
  // In & and |, not `parallel ? … : …`: that select of two comparisons
  // kept GCC from vectorising the lane loops.
  const bool outside = (parallel & (p > radius2)) | (!parallel & (g_min > radius2));
  span.t0 = span.t0 < lo ? lo : span.t0;
  span.t1 = hi < span.t1 ? hi : span.t1;
  span.enters = span.enters & !outside & (span.t0 <= span.t1);
}

// A fourth stage for signed glyphs: the span's end narrowed to the double
// cone about axis k, ‖q_⊥k‖ ≤ ρ (box − |q_k|), and the span dropped where
// the ray misses it: run on the lanes whose source has a point on axis k
// (`cone` 1; 0 leaves the lane's span to the bit). Its start stays where
// the box and cylinder put it: there the superquadric's gauge N is at
// least 1, and N falls no faster than σ√a, which the tracer's bound of a
// span not yet evaluated rests on (shape_trace.cpp, span_rate). At a
// cone's side only u ≥ 1, and u may fall 1.2 times as fast.
//
// The double cone is two solid cones, one from each apex q_k = ±box
// towards the other: where m = box ∓ q_k ≥ 0 and f = ρ² m² − ‖q_⊥k‖² ≥ 0,
// f(t0 + τ) = A τ² + 2 B τ + C along the ray, A the same for both. Within
// the box |q_k| < box, so m > 0 all along the span, and of the two cones
// that f ≥ 0 describes (the solid one and its mirror beyond the apex) only
// the solid one meets the span. So, each cone convex:
//  - A < 0 (the ray steeper than the cone's side): f ≥ 0 between its
//    roots, or nowhere;
//  - A > 0 (the ray within the cone's opening): f ≥ 0 outside them, the
//    solid cone's side the one where m grows, beyond the larger root if m
//    grows with t, else before the smaller.
// The quadratic is in τ = t − t0, about the span's start t0, a point of
// the box (|q| ≤ √3 box), not about the ray's origin: from a camera D
// glyph sizes away, C and B grow as D² and D, and C's rounding (ε D²)
// moved the roots as far, 10⁻⁵ of the glyph at D = 10⁵, past the widening
// below. The roots come as q/A and C/q, q = −(B + sgn B √(B² − AC)),
// which do not cancel, from one division. Where A nearly cancels (the ray
// along the cone's side) the cone cuts nothing. The cone is widened by
// 10⁻⁶ of itself, as the cylinder is, so round-off never cuts the glyph:
// a ray that grazes the true cone meets the widened one with a
// discriminant far above the rounding of B² − AC.
[[gnu::always_inline]] inline void clip_to_nappe(double m0, double m1, double a, bool decided, double b_across,
                                                 double c_across, double rho2, double t0, double& lo, double& hi,
                                                 bool& never) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double b = rho2 * (m0 * m1) - b_across, c = rho2 * (m0 * m0) - c_across;
  const double disc = b * b - a * c;
  const double root = std::sqrt(disc > 0.0 ? disc : 0.0);
  const double q = -(b + std::copysign(root, b));
  const double inverse = 1.0 / (a * q);  // q/A = q²/(Aq), C/q = AC/(Aq)
  const double r1 = (q * q) * inverse, r2 = q != 0.0 ? (a * c) * inverse : r1;
  const double low = t0 + (r1 < r2 ? r1 : r2), high = t0 + (r1 < r2 ? r2 : r1);
  const bool opening = a > 0.0;
  const double f_lo = !decided ? -inf : (opening ? (m1 > 0.0 ? high : -inf) : low);
  const double f_hi = !decided ? inf : (opening ? (m1 > 0.0 ? inf : low) : high);
  lo = lo < f_lo ? f_lo : lo;
  hi = f_hi < hi ? f_hi : hi;
  never = never | (decided & !opening & (disc < 0.0));
}

template <int K>
[[gnu::always_inline]] inline void clip_to_cone(const ScaledRay& r, double box, double cone, LaneSpan& span) {
  constexpr double rho2 = (kConeBase * (1.0 + 1e-6)) * (kConeBase * (1.0 + 1e-6));
  constexpr int k = K, i = (K + 1) % 3, j = (K + 2) % 3;
  const double apex = box * (1.0 + 1e-6);
  const double t0 = span.t0;  // q(t0 + τ) = p + τ wd
  const double p_k = r.wp[k] + t0 * r.wd[k], p_i = r.wp[i] + t0 * r.wd[i], p_j = r.wp[j] + t0 * r.wd[j];
  const double a_across = r.wd[i] * r.wd[i] + r.wd[j] * r.wd[j];
  const double b_across = r.wd[i] * p_i + r.wd[j] * p_j;
  const double c_across = p_i * p_i + p_j * p_j;
  const double steep = rho2 * (r.wd[k] * r.wd[k]);
  const double a = steep - a_across;
  const bool decided = std::fabs(a) > 1e-6 * (steep + a_across);
  double lo = span.t0, hi = span.t1;
  bool never = false;
  clip_to_nappe(apex - p_k, -r.wd[k], a, decided, b_across, c_across, rho2, t0, lo, hi, never);
  clip_to_nappe(apex + p_k, r.wd[k], a, decided, b_across, c_across, rho2, t0, lo, hi, never);
  const bool cut = cone != 0.0;
  span.t1 = cut ? hi : span.t1;
  span.enters = span.enters & !(cut & (never | (lo > hi)));
}

// The least value of a vertex form on the span: where the span comes
// nearest its vertex.
[[gnu::always_inline]] inline double least_on_span(const VertexForm& f, const LaneSpan& span) {
  const double above = f.t_v < span.t0 ? span.t0 : f.t_v;
  const double d = (above > span.t1 ? span.t1 : above) - f.t_v;
  return f.a * d * d + f.g_v;
}

// Both narrowings of a shape's span, its box, then its cylinder, and the
// span's lower bound of g: of the slabs' and the cylinder's bounds, the one
// whose least value on the span is largest, if that is larger than g_e's
// there (g_e's own otherwise, finish_span). A sharp glyph's g_e is up to
// three times too small on its faces, where the slabs are exact; a disc's
// rim is the cylinder's. Only one is kept, in g_e's form, so the tracer's
// bounds cost no more (RaySpan::lower_a). On fig05 as superquadrics, 960²,
// one sample: 3.72 -> 2.27 probes a shadow ray, 0.53 -> 0.43 a camera
// ray. Each is shrunk by 10⁻⁶ of itself, as σ is for g_e, against the
// rounding of t − t_v where t is far larger.
[[gnu::always_inline]] inline void clip_to_support(const ScaledRay& r, double box, double radius, const double (&across)[3],
                            LaneSpan& span) {
  VertexForm slabs[3], wall;
  clip_to_box(r, box, span, slabs);
  clip_to_cylinder(r, radius, across, span, wall);
  double best = least_on_span(span.lower, span);
  const auto keep_if_better = [&](VertexForm f) {
    f.a *= 1.0 - 1e-6, f.g_v *= 1.0 - 1e-6;
    const double least = least_on_span(f, span);
    const bool better = least > best;
    best = better ? least : best;
    span.lower.a = better ? f.a : span.lower.a;
    span.lower.t_v = better ? f.t_v : span.lower.t_v;
    span.lower.g_v = better ? f.g_v : span.lower.g_v;
  };
  for (const VertexForm& f : slabs) keep_if_better(f);
  keep_if_better(wall);
}

[[gnu::always_inline]] inline void store(const LaneSpan& span, SpanLanes& spans, int i) {
  spans.t0[i] = span.t0;
  spans.t1[i] = span.t1;
  spans.a[i] = span.a;
  spans.t_c[i] = span.t_c;
  spans.g_min[i] = span.g_min;
  spans.lower_a[i] = span.lower.a;
  spans.lower_t[i] = span.lower.t_v;
  spans.lower_g[i] = span.lower.g_v;
}

// Lane i of `spans`, as the first two stages left it, narrowed by the third
// (clip_to_support). `inside` is whether the ray entered the ellipsoid's
// support, and becomes whether it enters the shape's.
[[gnu::always_inline]] inline void narrow_lane(const ScaledRay& r, double box, double radius,
                                               const double (&across)[3], SpanLanes& spans, int i,
                                               std::int64_t& inside) {
  LaneSpan span{spans.t0[i],
                spans.t1[i],
                spans.a[i],
                spans.t_c[i],
                spans.g_min[i],
                {spans.lower_a[i], spans.lower_t[i], spans.lower_g[i]},
                inside != 0};
  clip_to_support(r, box, radius, across, span);
  store(span, spans, i);
  inside = span.enters;
}

// And by the fourth on axis k (clip_to_cone): only the span's end and
// whether it enters change.
template <int K>
[[gnu::always_inline]] inline void cone_lane(const ScaledRay& r, double box, double cone, SpanLanes& spans, int i,
                                             std::int64_t& inside) {
  LaneSpan span{spans.t0[i], spans.t1[i], 0.0, 0.0, 0.0, {}, inside != 0};
  clip_to_cone<K>(r, box, cone, span);
  spans.t1[i] = span.t1;
  inside = span.enters;
}

// How far a kernel narrows a span: not at all (the ellipsoid), to the box
// and cylinder, or to those and the double cones.
enum class Narrowing { none, boxed, pointed };

// The lane loops. They have no branches, so the compiler turns them into
// SIMD at whatever width the instruction set of the function they are
// inlined into allows (below): the same operations in the same order on
// every lane, so every variant gives the same bits. A shape's box and
// cylinder are a second loop, run only when some lane's ray enters the
// ellipsoid's support: in 53% of the span query's calls on fig05 as
// superquadrics none does, and the third stage costs more than the first
// two. (The second loop works out each lane's scaled ray again, the same
// bits, rather than store and load it.) A signed glyph's cones are a loop
// an axis after that, while some lane is still inside.
//
// The stages and the lambdas are forced inline: with the cones' loops and
// kernels more callers, GCC left `scaled` and clip_to_support out of line,
// and a loop that calls a function is not vectorised (the box's loop ran
// one lane at a time, and superquadrics' renders took a quarter longer).
// The cone's axis is a constant for the same reason: a ray's components
// indexed by a variable kept its loop from vectorising.
template <Narrowing N>
__attribute__((always_inline)) inline unsigned ray_spans_lanes(const BlobSource& s, const ShapeSupport& support,
                                                               const RayLanes& __restrict rays, int first, int count,
                                                               SpanLanes& __restrict spans) {
  const double w[9] = {s.w[0], s.w[1], s.w[2], s.w[3], s.w[4], s.w[5], s.w[6], s.w[7], s.w[8]};
  const double cx = s.centre[0], cy = s.centre[1], cz = s.centre[2];
  const double box = support.box, radius = support.radius;
  double across[3];
  components_across(support.axis, across);
  std::int64_t inside[kMaxPacket];  // as wide as a double, so the loop keeps one vector width
  const int end = first + count;
  const auto scaled = [&](int i) __attribute__((always_inline)) {
    return scaled_ray(w, cx, cy, cz, rays.ox[i], rays.oy[i], rays.oz[i], rays.dx[i], rays.dy[i], rays.dz[i]);
  };
  const auto mask = [&]() __attribute__((always_inline)) {
    unsigned bits = 0;
    for (int i = first; i < end; ++i) bits |= unsigned(inside[i]) << i;
    return bits;
  };
  for (int i = first; i < end; ++i) {
    const LaneSpan span = finish_span(scaled(i), rays.tmin[i], rays.tmax[i]);
    store(span, spans, i);
    inside[i] = span.enters;
  }
  if (N == Narrowing::none || mask() == 0) return mask();
  for (int i = first; i < end; ++i) narrow_lane(scaled(i), box, radius, across, spans, i, inside[i]);
  // (A glyph in tension every way has no point.)
  if (N == Narrowing::pointed) {
    const auto cones = [&](auto axis) __attribute__((always_inline)) {
      if ((support.pointed & (1u << axis.value)) && mask() != 0)
        for (int i = first; i < end; ++i) cone_lane<axis.value>(scaled(i), box, 1.0, spans, i, inside[i]);
    };
    cones(std::integral_constant<int, 0>{}), cones(std::integral_constant<int, 1>{}),
        cones(std::integral_constant<int, 2>{});
  }
  return mask();
}

// The same formula the other way round: one ray against a packet of
// sources (a bundle of short rays tested against the sources near them).
template <Narrowing N>
__attribute__((always_inline)) inline unsigned source_spans_lanes(const SourceLanes& __restrict sources, const Vec3& o,
                                                                  const Vec3& d, double tmin, double tmax,
                                                                  SpanLanes& __restrict spans) {
  const double ox = o.x(), oy = o.y(), oz = o.z(), dx = d.x(), dy = d.y(), dz = d.z();
  std::int64_t inside[kMaxPacket];
  const auto scaled = [&](int i) __attribute__((always_inline)) {
    const double w[9] = {sources.w[0][i], sources.w[1][i], sources.w[2][i], sources.w[3][i], sources.w[4][i],
                         sources.w[5][i], sources.w[6][i], sources.w[7][i], sources.w[8][i]};
    return scaled_ray(w, sources.c[0][i], sources.c[1][i], sources.c[2][i], ox, oy, oz, dx, dy, dz);
  };
  const auto mask = [&]() __attribute__((always_inline)) {
    unsigned bits = 0;
    for (int i = 0; i < kMaxPacket; ++i) bits |= unsigned(inside[i]) << i;
    return bits & ((1u << sources.count) - 1u);
  };
  for (int i = 0; i < kMaxPacket; ++i) {  // all lanes: unused ones hold a source that never matches
    const LaneSpan span = finish_span(scaled(i), tmin, tmax);
    store(span, spans, i);
    inside[i] = span.enters;
  }
  if (N == Narrowing::none || mask() == 0) return mask();
  for (int i = 0; i < kMaxPacket; ++i) {
    const double across[3] = {sources.across[0][i], sources.across[1][i], sources.across[2][i]};
    narrow_lane(scaled(i), sources.box[i], sources.radius[i], across, spans, i, inside[i]);
  }
  if (N == Narrowing::pointed) {
    const auto cones = [&](auto axis) __attribute__((always_inline)) {
      if ((sources.pointed & (1u << axis.value)) && mask() != 0)
        for (int i = 0; i < kMaxPacket; ++i)
          cone_lane<axis.value>(scaled(i), sources.box[i], sources.cone[axis.value][i], spans, i, inside[i]);
    };
    cones(std::integral_constant<int, 0>{}), cones(std::integral_constant<int, 1>{}),
        cones(std::integral_constant<int, 2>{});
  }
  return mask();
}

// One variant of each loop, with and without the box, per instruction set
// (isa_variants.h).
#define HSB_SPAN_KERNELS(suffix, target_isa)                                                                      \
  template <Narrowing N>                                                                                          \
  __attribute__((target(target_isa))) unsigned ray_spans_##suffix(                                               \
      const BlobSource& s, const ShapeSupport& support, const RayLanes& __restrict rays, int first, int count,    \
      SpanLanes& __restrict spans) {                                                                              \
    return ray_spans_lanes<N>(s, support, rays, first, count, spans);                                             \
  }                                                                                                               \
  template <Narrowing N>                                                                                          \
  __attribute__((target(target_isa))) unsigned source_spans_##suffix(const SourceLanes& __restrict sources,       \
                                                                     const Vec3& o, const Vec3& d, double tmin,   \
                                                                     double tmax, SpanLanes& __restrict spans) {  \
    return source_spans_lanes<N>(sources, o, d, tmin, tmax, spans);                                               \
  }

HSB_FOR_EACH_ISA(HSB_SPAN_KERNELS)
#undef HSB_SPAN_KERNELS

#define HSB_KERNEL_SET(suffix)                                                                           \
  {ray_spans_##suffix<Narrowing::none>,    ray_spans_##suffix<Narrowing::boxed>,                                \
   ray_spans_##suffix<Narrowing::pointed>, source_spans_##suffix<Narrowing::none>,                              \
   source_spans_##suffix<Narrowing::boxed>, source_spans_##suffix<Narrowing::pointed>}
// In InstructionSet order.
constexpr SpanKernels kKernels[] = {HSB_KERNEL_SET(sse2), HSB_KERNEL_SET(sse42), HSB_KERNEL_SET(avx),
                                    HSB_KERNEL_SET(avx2), HSB_KERNEL_SET(avx512)};
#undef HSB_KERNEL_SET

}  // namespace

const SpanKernels& span_kernels(InstructionSet isa) { return kKernels[std::size_t(isa)]; }

// The span BVH's callback spends most of a render here, one source against
// a packet of rays.
unsigned ray_spans(const BlobSource& s, const ShapeSupport& support, const RayLanes& rays, int first, int count,
                   SpanLanes& spans) {
  const SpanKernels& kernels = span_kernels(active_isa());
  const SpanKernels::RaySpans kernel =
      support.pointed ? kernels.ray_spans_pointed : (support.bounded() ? kernels.ray_spans_boxed : kernels.ray_spans);
  return kernel(s, support, rays, first, count, spans);
}

unsigned source_spans(const SourceLanes& sources, const Vec3& o, const Vec3& d, double tmin, double tmax,
                      SpanLanes& spans) {
  const SpanKernels& kernels = span_kernels(active_isa());
  const SpanKernels::SourceSpans kernel = sources.pointed ? kernels.source_spans_pointed
                                          : (sources.boxed ? kernels.source_spans_boxed : kernels.source_spans);
  return kernel(sources, o, d, tmin, tmax, spans);
}

bool ray_span(const BlobSource& s, std::uint32_t index, std::uint32_t rank, const Vec3& o, const Vec3& d, double tmin,
              double tmax, RaySpan& span, const ShapeSupport& support) {
  // Scalar: a lone ray would pay more for the packet version's dispatch and
  // lane set-up than it saves.
  const double w[9] = {s.w[0], s.w[1], s.w[2], s.w[3], s.w[4], s.w[5], s.w[6], s.w[7], s.w[8]};
  const ScaledRay r = scaled_ray(w, s.centre[0], s.centre[1], s.centre[2], o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
  if (!r.line_enters()) return false;
  LaneSpan lane = finish_span(r, tmin, tmax);
  if (lane.enters && support.bounded()) {
    double across[3];
    components_across(support.axis, across);
    clip_to_support(r, support.box, support.radius, across, lane);
    if (lane.enters && (support.pointed & 1u)) clip_to_cone<0>(r, support.box, 1.0, lane);
    if (lane.enters && (support.pointed & 2u)) clip_to_cone<1>(r, support.box, 1.0, lane);
    if (lane.enters && (support.pointed & 4u)) clip_to_cone<2>(r, support.box, 1.0, lane);
  }
  if (!lane.enters) return false;
  span = RaySpan{lane.t0, lane.t1, lane.a, lane.t_c, lane.g_min, index, rank, lane.lower.a, lane.lower.t_v,
                 lane.lower.g_v, lane.t0};
  return true;
}

bool narrow_to_influence(GlyphShape shape, const Box3& influence, const Vec3& o, const Vec3& d, RaySpan& span) {
  if (shape_is_quadric(shape)) return true;
  const auto [t0, t1] = ray_interval_in(influence, o, d, span.t0, span.t1);
  if (!(t0 <= t1)) return false;
  span.box_t0 = t0, span.t1 = t1;
  return true;
}

}  // namespace hsb
