#pragma once
// One source seen along a ray: g(t) along the ray and the t-interval where
// g ≤ 1 (the source's support on the ray). Computed for a whole packet of
// rays at once, because that is how the span BVH asks.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "base/vec3.h"
#include "renderer/surface/blob_field.h"
#include "renderer/surface/instruction_set.h"

namespace hsb {

// Rays traced together: Embree's 16-wide packets, a 4×4 tile of camera rays
// or their shadow rays.
constexpr int kMaxPacket = 16;

// g is kept in vertex form g(t) = a (t − t_c)² + g_min rather than expanded,
// which would cancel catastrophically for a distant camera.
struct RaySpan {
  double t0, t1;    // support interval, clipped to the ray's [tmin, tmax]
  double a;         // dᵀMd > 0: also the square of g's directional rate
  double t_c;       // closest approach: K rises before it and falls after it
  double g_min;     // g(t_c)
  std::uint32_t source;
  std::uint32_t rank = 0;  // the source's spatial rank (spatial_rank.h): the order a ray's spans are kept in
  // The glyph-shape tracer's lower bound of the shape's own g on [t0, t1],
  // in the same vertex form: g ≥ lower_a (t − lower_t)² + lower_g. g_e's
  // quadratic above, or a tighter one from the shape's box or cylinder
  // (ray_span.cpp, clip_to_support).
  double lower_a = 0.0, lower_t = 0.0, lower_g = 0.0;
  // Where the ray enters the source's influence box, at or after t0
  // (narrow_to_influence): nothing of the support lies before it. Which
  // spans a crossing keeps beyond the first entry it proves is decided by
  // it (FieldRay::drop_spans_beyond_first_entry).
  double box_t0 = 0.0;

  double g(double t) const { return a * (t - t_c) * (t - t_c) + g_min; }
  // The lower bound's least value on [t0, t1].
  double least_lower_g() const {
    const double d = std::clamp(lower_t, t0, t1) - lower_t;
    return lower_a * d * d + lower_g;
  }
};

// Where g is smallest on the span: the source's peak along the ray.
inline double peak_t(const RaySpan& s) { return s.t_c < s.t0 ? s.t0 : (s.t_c > s.t1 ? s.t1 : s.t_c); }

// Up to kMaxPacket rays o + t d, t ∈ [tmin, tmax], as structure of arrays:
// one source is tested against all of them in SIMD lanes.
struct RayLanes {
  alignas(64) double ox[kMaxPacket], oy[kMaxPacket], oz[kMaxPacket];
  alignas(64) double dx[kMaxPacket], dy[kMaxPacket], dz[kMaxPacket];
  alignas(64) double tmin[kMaxPacket], tmax[kMaxPacket];

  void set(int lane, const Vec3& o, const Vec3& d, double t_min, double t_max) {
    ox[lane] = o.x(), oy[lane] = o.y(), oz[lane] = o.z();
    dx[lane] = d.x(), dy[lane] = d.y(), dz[lane] = d.z();
    tmin[lane] = t_min, tmax[lane] = t_max;
  }
  Vec3 origin(int lane) const { return {ox[lane], oy[lane], oz[lane]}; }
  Vec3 direction(int lane) const { return {dx[lane], dy[lane], dz[lane]}; }
};

// A shape other than the ellipsoid has its support inside the box
// |q_k| ≤ box (each k) of the stored frame, box = 1/σ (glyph_shape.h), much
// tighter than the bounding ellipsoid for a sharp glyph, and inside the
// cylinder ‖q_⊥‖ ≤ radius about its symmetry axis, q_⊥ the two other
// components and radius = support_cylinder_radius/σ: a round glyph leaves
// the corners of the box's cross-section empty. The span functions below
// narrow each span to both when given them: a ray through the ellipsoid's
// corners past the box collects nothing, which for sharp glyphs is a third
// to a half of what the ellipsoids gather, and a ray past the cylinder
// nothing either. kNoBox: the support is the ellipsoid's own.
constexpr double kNoBox = std::numeric_limits<double>::infinity();

// A signed glyph's support is also inside the double cone about each axis
// k that ends in points, ‖q_⊥k‖ ≤ ρ (box − |q_k|) (u ≥ C_k, glyph_shape.h):
// a ray through the cylinder that passes beside a point meets nothing of
// it, and one that leaves through a point's side has left it. Under the
// point load, where glyphs are compressed every way, the cones leave a
// shadow ray on fig08 21 of the 78 spans the box and cylinder let through.
struct ShapeSupport {
  double box = kNoBox;     // |q_k| ≤ box on every axis
  double radius = kNoBox;  // ‖q_⊥‖ ≤ radius across `axis`
  int axis = 2;            // the symmetry axis, a row of W
  unsigned pointed = 0;    // bit k: inside the double cone about axis k too
  bool bounded() const { return box != kNoBox; }
};

// The cylinder's axis as the span kernels take it, a factor a component
// rather than an index (their lanes have no branches): 1 for the two
// components across `axis`, 0 for the axis's own.
inline void components_across(int axis, double (&across)[3]) {
  for (int k = 0; k < 3; ++k) across[k] = k == axis ? 0.0 : 1.0;
}

// Source i's box and cylinder, or none for the ellipsoid.
inline ShapeSupport source_support(const BlobField& field, std::size_t i) {
  if (shape_is_quadric(field.shape)) return {};
  const ShapeParams& shape = field.shapes[i];
  const double box = 1.0 / double(shape.bound_scale);
  return {box, support_cylinder_radius(shape) * box, shape.axis, shape.pointed};
}

// The double cones as the span kernels take them, a factor an axis: 1
// where bit k of `pointed` is set, else 0.
inline void cone_factors(unsigned pointed, double (&cone)[3]) {
  for (int k = 0; k < 3; ++k) cone[k] = pointed & (1u << k) ? 1.0 : 0.0;
}

// The spans of one source on lanes [first, first + count) of `rays`, in the
// same lanes of `spans` (fields t0 to g_min and lower_*; `source` is left to
// the caller). Returns a bit mask of the lanes whose ray enters the
// source's support.
struct SpanLanes {
  alignas(64) double t0[kMaxPacket], t1[kMaxPacket], a[kMaxPacket], t_c[kMaxPacket], g_min[kMaxPacket];
  alignas(64) double lower_a[kMaxPacket], lower_t[kMaxPacket], lower_g[kMaxPacket];

  // Lane i as the span of source number `source`, of spatial rank `rank`.
  RaySpan span(int i, std::uint32_t source, std::uint32_t rank) const {
    return RaySpan{t0[i], t1[i], a[i], t_c[i], g_min[i], source, rank, lower_a[i], lower_t[i], lower_g[i], t0[i]};
  }
  // The same appended to `list`, written there field by field: a span
  // made on the stack and copied in whole was read back in 16-byte pieces
  // of what had been stored in 8-byte ones, a store-forwarding stall that
  // took a third of the span query's callback.
  void append(int i, std::uint32_t source, std::uint32_t rank, std::vector<RaySpan>& list) const {
    RaySpan& s = list.emplace_back();
    s.t0 = t0[i], s.t1 = t1[i], s.a = a[i], s.t_c = t_c[i], s.g_min = g_min[i];
    s.lower_a = lower_a[i], s.lower_t = lower_t[i], s.lower_g = lower_g[i];
    s.source = source, s.rank = rank, s.box_t0 = t0[i];
  }
};

// A collected span narrowed to its source's influence box (influence_bounds):
// its end to where the ray leaves the box, and box_t0 to where it enters;
// false where the ray misses the box on the span (a span of an ellipsoid
// is left as it is: its box holds it). A shape's box is its support's own
// extent, and a signed glyph's that of its cones, tighter than the bounds
// a span is cut from (its ellipsoid, box and cylinder; a pointed span
// begins where those do), so a span can begin before its box, or lie
// beside it. The span BVH finds a source only where the ray crosses its
// box, and stops at the first entry it proves (blob_geometry.cpp,
// prune_beyond_entry): whether it collected a span whose box begins past
// that entry depends on the order the traversal met the boxes in, and a
// list of nearby sources, which tests no source's own box, collects spans
// beside their boxes that the traversal does not; the crossing would move
// in its last bits. The support lies inside the box, so nothing of it is
// cut off. t0 stays where the span's own bounds begin, where u ≥ N ≥ 1 and
// the tracer's bound of a span not yet evaluated starts to fall (from a
// cone's side only u ≥ 1 holds, and the walk, a bound that jumped where
// such a span began, crept towards each: fig08 as signed glyphs took 24 %
// more time).
bool narrow_to_influence(GlyphShape shape, const Box3& influence, const Vec3& o, const Vec3& d, RaySpan& span);
// `support`: the source's (source_support).
unsigned ray_spans(const BlobSource& s, const ShapeSupport& support, const RayLanes& rays, int first, int count,
                   SpanLanes& spans);

// Up to kMaxPacket sources as structure of arrays, W's rows, the centres
// and the boxes in double: one ray is tested against all of them in SIMD
// lanes.
struct SourceLanes {
  alignas(64) double w[9][kMaxPacket];
  alignas(64) double c[3][kMaxPacket];
  // Read when `boxed`: each source's ShapeSupport, its axis as
  // components_across gives it (and when `pointed`, its cones as
  // cone_factors gives them).
  alignas(64) double box[kMaxPacket], radius[kMaxPacket];
  alignas(64) double across[3][kMaxPacket];
  alignas(64) double cone[3][kMaxPacket];
  std::uint32_t index[kMaxPacket];
  std::uint32_t rank[kMaxPacket];
  int count = 0;  // lanes [0, count) hold sources
  bool boxed = false;  // whether the sources' spans are narrowed to their boxes and cylinders
  unsigned pointed = 0;  // the axes some source's span is narrowed to the double cone about

  // Lane `lane`'s support.
  void set_support(int lane, const ShapeSupport& support) {
    box[lane] = support.box, radius[lane] = support.radius;
    double factors[3];
    components_across(support.axis, factors);
    for (int k = 0; k < 3; ++k) across[k][lane] = factors[k];
    cone_factors(support.pointed, factors);
    for (int k = 0; k < 3; ++k) cone[k][lane] = factors[k];
  }
};

// The spans of the ray o + t d, t ∈ [tmin, tmax], on the sources of
// `sources`: lane i of `spans` is source i's. Returns a bit mask of the
// sources whose support the ray enters.
unsigned source_spans(const SourceLanes& sources, const Vec3& o, const Vec3& d, double tmin, double tmax,
                      SpanLanes& spans);

// The two lane loops above compiled for one instruction set, without
// boxes, with boxes and cylinders, and with those and double cones;
// ray_spans() and source_spans() call those of active_isa(). Every variant
// gives the same bits (the tests hold them to it), and the pointed ones on
// a support without points those of the boxed ones.
struct SpanKernels {
  using RaySpans = unsigned (*)(const BlobSource& s, const ShapeSupport& support, const RayLanes& rays, int first,
                                int count, SpanLanes& spans);
  using SourceSpans = unsigned (*)(const SourceLanes& sources, const Vec3& o, const Vec3& d, double tmin,
                                   double tmax, SpanLanes& spans);
  RaySpans ray_spans, ray_spans_boxed, ray_spans_pointed;
  SourceSpans source_spans, source_spans_boxed, source_spans_pointed;
  // The ray kernel for the sources of a field of `shape`.
  RaySpans for_shape(GlyphShape shape) const {
    return shape_is_quadric(shape) ? ray_spans
                                   : (shape == GlyphShape::signed_superquadric ? ray_spans_pointed : ray_spans_boxed);
  }
};
const SpanKernels& span_kernels(InstructionSet isa);

// The same for one ray: fills `span` and returns true when the ray enters
// the support of `s` (source number `index`, spatial rank `rank`, its box
// and cylinder `support`).
bool ray_span(const BlobSource& s, std::uint32_t index, std::uint32_t rank, const Vec3& o, const Vec3& d, double tmin,
              double tmax, RaySpan& span, const ShapeSupport& support = {});

}  // namespace hsb
