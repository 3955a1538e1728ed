#pragma once
// The glyph's distance function: the one place that knows a source's
// shape. A source's influence is K(g) with g = u², u its distance from the
// centre in the glyph's scaled frame, 1 at the edge of its influence.
//
// Every shape keeps a bounding ellipsoid in the source record: the stored
// matrix W_s (blob_field.h) gives the quadratic g_e = |W_s (x − c)|², and
// each shape guarantees g_e ≤ g, so K(g) ≤ K(g_e). The spans, the span BVH's
// boxes, the peaks and the running polynomial bound of F (field_bound.h)
// are all computed from g_e: they are upper bounds of the influence for
// every shape, and exact for the ellipsoid; a shape's spans are then
// narrowed to the box |q_s,k| ≤ 1/σ and the cylinder about its symmetry
// axis that hold its support (ray_span.h, support_cylinder_radius), and
// its boxes are theirs where tighter (influence_bounds). What must
// be exact (F itself, its gradient, the slope bound of sphere tracing)
// asks the shape here.
//
//  - ellipsoid: u = |q| with q = W (x − c), W = diag(1/(R r_k)) Vᵀ (paper
//    eq. 11). W_s = W, g = g_e: quadratic along a ray, so F is a polynomial
//    between support endpoints for the polynomial kernels and the exact
//    intersector applies.
//  - superquadric (Kindlmann 2004): u = N(q), the superquadric gauge
//      N(q) = ‖(‖(q_a, q_b)‖_{2/α}, q_z)‖_{2/β},
//    with z the symmetry axis and (a, b) the other two. N is a norm for
//    α, β ≤ 2 and its unit ball lies in the cube [−1, 1]³ (N ≥ max|q_k|).
//    Each source's bound scale σ = max |q|/N(q) over directions (1 for
//    the ellipsoid's exponents, at most √3 for a cube) gives W_s = W/σ:
//    g_e = |q|²/σ² ≤ N². For α, β ≤ 1 (every sharpness ≥ 0) N ≤ |q| and N
//    is 1-Lipschitz in q (|∇N| ≤ 1, Schultz and Kindlmann's nested norms),
//    so along a ray N changes at most σ times as fast as √g_e (the
//    tracer's bound for a source it has not reached, shape_trace.cpp:
//    span_rate, which holds for every shape, as u ≥ N).
//    N is C¹ away from the centre for
//    0 < α, β < 2: the "edges" of sharp glyphs are bands of high curvature,
//    not creases, so the gradient is defined everywhere on the surface
//    (each norm is evaluated divided by its largest term, so exponents of
//    10⁶ stay finite).
//  - signed: the superquadric of the radii with a cone's point at both
//    ends of every compressive axis k, u = max(N(q), C_k(q)) with the
//    double cone C_k(q) = ‖q_⊥k‖/ρ + |q_k| (apex at q_k = ±1, base radius
//    ρ = kConeBase). A maximum of norms is a norm, so the glyph stays
//    convex, u stays convex along every ray and N ≤ u keeps σ and the
//    cube; C_k ≤ √(1 + 1/ρ²)|q|, so u is Lipschitz with that constant
//    (ShapeParams::lipschitz) instead of 1. Tension ends are the
//    superquadric's flat or round faces, compression ends are points:
//    the sign reads without colour, and a definite compression (three
//    points) differs from a definite tension (none), which Schultz and
//    Kindlmann's 2010 glyph, the same for T and −T, does not show. Their
//    concave "thorns" (exponents up to 3) are left out on purpose: a
//    non-convex gauge has no Lipschitz constant at its cusps, and the
//    tracer's proofs rest on convexity. The gradient is the larger
//    branch's (on the crease where they meet either is a subgradient,
//    which is all the tangent bounds need); at a cone's apex its radial
//    part is taken as 0.

#include <array>
#include <cstdint>
#include <vector>

#include "base/vec3.h"
#include "field/glyphs/sign_convention.h"

namespace hsb {

enum class GlyphShape { ellipsoid, superquadric, signed_superquadric };
// The name a scene gives it (glyphs.shape): "ellipsoid", "superquadric", "signed".
const char* glyph_shape_name(GlyphShape shape);

// The signed glyph's cone base radius ρ, in the glyph's scaled frame: its
// points have a half-angle of atan ρ ≈ 56° and replace the faces beyond
// 0.38 of the way out.
constexpr double kConeBase = 1.5;

// A source's shape beyond its axes and radii; the ellipsoid has none.
struct ShapeParams {
  float alpha = 1.0f, beta = 1.0f;  // superquadric: equatorial and axial exponents
  // σ: W_s = W/σ bounds the influence (g_e ≤ g), and u's rate along a ray
  // is at most Lσ times √g_e's (L below), N's σ times.
  float bound_scale = 1.0f;
  std::uint8_t axis = 2;            // superquadric: the symmetry axis, a row of W (0, 1 or 2)
  std::uint8_t pointed = 0;         // signed: bit k set when axis k (row k of W) is compressive
  // Largest |∇u| in the glyph's own frame q = σ q_s: 1, or √(1 + 1/ρ²)
  // with a point.
  float lipschitz = 1.0f;
};
// The radius of the cylinder about the symmetry axis that holds a
// superquadric's support, in the glyph's own frame q = σ q_s: N ≤ 1 needs
// the equatorial ‖(q_a, q_b)‖_{2/α} ≤ 1, and a 2/α-norm of a pair is at
// least 2^{α/2 − 1/2} times its length when α ≤ 1 (at least the length
// when α > 1), so ‖(q_a, q_b)‖₂ ≤ 2^{max(0, 1 − α)/2}. Kindlmann's glyphs
// are round about their axis (α near 1): a ray past the corners of the
// cube's cross-section, a fifth of it, meets nothing. A signed glyph's
// u ≥ N keeps it inside the same cylinder. Rounded up by 10⁻⁶, as σ.
double support_cylinder_radius(const ShapeParams& params);

// How far a superquadric's support N(q) ≤ 1 reaches along a, in the
// glyph's own frame q = σ q_s: max a·q over it, its support function,
// which is N's dual norm. N nests a 2/α-norm in a 2/β-norm, and the dual
// of such a nest is the nest of the duals,
//   h(a) = ‖(‖(a_a, a_b)‖_{2/(2−α)}, a_z)‖_{2/(2−β)},
// so an aslant glyph's box is its support's own, where the cube and
// cylinder that hold it overshoot (influence_bounds). Rounded up by 10⁻⁶,
// as σ.
double superquadric_reach(const ShapeParams& params, const Vec3& a);

// Whether g is the quadratic g_e itself: F is then a polynomial along a ray
// for the polynomial kernels (the exact intersector), one source alone is
// entered where g_e reaches its level, and a source past its closest
// approach only falls.
inline bool shape_is_quadric(GlyphShape shape) { return shape == GlyphShape::ellipsoid; }

// g = u² at q_s = W_s (x − c), the point in the stored (bounding) frame
// (for the ellipsoid, |q_s|² whatever the parameters).
double shape_g(GlyphShape shape, const ShapeParams& params, const Vec3& q_s);
// g and its gradient with respect to q_s (the world gradient is W_sᵀ times it).
double shape_g_gradient(GlyphShape shape, const ShapeParams& params, const Vec3& q_s, Vec3& gradient);

// u = √g at q_s and, through du_dt, its rate of change along v_s: the ray
// q_s(t) = q0 + t v_s in the stored frame. u is convex along every ray for
// both shapes (a norm of q), so du/dt never falls as t grows: past the
// closest approach it stays ≥ 0, and before it |du/dt| only shrinks. The
// sphere tracer's slope bound rests on that.
double shape_u_rate(GlyphShape shape, const ShapeParams& params, const Vec3& q_s, const Vec3& v_s, double& du_dt);
// shape_u_rate() of many glyphs at once, each at its point of its ray
// (the tracer's probes): the superquadric's gauges go through SIMD lanes
// (superquadric_gauge.h), with the same bits as one at a time.
struct ShapeSample {
  const ShapeParams* params;
  Vec3 q_s, v_s;
};
void shape_u_rates(GlyphShape shape, const ShapeSample* samples, int count, double* u, double* du_dt);
// shape_g_gradient() of many glyphs at once (the shading), v_s unused.
void shape_g_gradients(GlyphShape shape, const ShapeSample* samples, int count, double* g, Vec3* gradient);

// A lower bound of a signed glyph's u over [lo, hi] of the ray
// q_s(t) = q0 + t v in the stored frame: the largest over its points of
// the least its double cone C_k takes there (0 for a glyph without
// points), in closed form. The box and cylinder that bound every
// superquadric's support (ray_span.h) are loose about a point, and a ray
// leaving a point's face sees nothing else of it before a gauge.
double least_point_u(const ShapeParams& params, const Vec3& q0, const Vec3& v, double lo, double hi);

// The ray's first t in [lo, hi] with u(q0 + t v) ≤ u_level, or −1: Newton's
// method from lo on the convex u − u_level, whose every iterate stays at or
// before the first root (a convex function lies above its tangents), so it
// converges from one side without overshooting; where du/dt ≥ 0 while
// still outside, the ray has passed its closest approach and never enters.
double shape_entry(GlyphShape shape, const ShapeParams& params, const Vec3& q0, const Vec3& v, double u_level,
                   double lo, double hi);

// Kindlmann's superquadric for a glyph of radii r (in W's row order):
// Westin's measures of the radii sorted by size (westin_measures), c_l = (ρ1 − ρ2)/Σρ and
// c_p = 2(ρ2 − ρ3)/Σρ, each at most 0.99; a linear glyph (c_l > c_p) is
// round about its longest axis with α = (1 − c_p)^γ, β = (1 − c_l)^γ, a
// planar one about its shortest with α = (1 − c_l)^γ, β = (1 − c_p)^γ.
// γ = `sharpness` (Teem's `tend glyph -sh`); 0 gives the ellipsoid's
// exponents.
ShapeParams superquadric_params(const Vec3& radii, double sharpness);

// The signed glyph: superquadric_params(radii, sharpness) with a point on
// every axis whose eigenvalue is compressive under `sign` and larger than
// a thousandth of the largest in magnitude (a zero eigenvalue's noise
// must not flicker points on and off).
ShapeParams signed_params(const Vec3& radii, const Vec3& eigenvalues, double sharpness, SignConvention sign);

// superquadric_params (shape = superquadric) or signed_params (signed) of
// each glyph, the same values as one at a time: σ's searches of several
// glyphs run side by side in the gauge's lanes, and the glyphs are shared
// among the cores (33,768 glyphs of Teem's helix: 0.5 s -> 0.05 s).
// `eigenvalues` is read for signed glyphs only.
std::vector<ShapeParams> shape_params(GlyphShape shape, const std::vector<Vec3>& radii,
                                      const std::vector<Vec3>& eigenvalues, double sharpness, SignConvention sign);

}  // namespace hsb
