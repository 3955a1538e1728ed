#pragma once
// One source alone along a ray: where its own level surface K = C lies.
// Every kernel is non-negative, so where one source alone reaches C the
// blended field does too; that bounds the first crossing from above, and
// for a union of glyphs (blend = "max") it is the whole answer.

#include <algorithm>
#include <cmath>

#include "renderer/surface/blob_field.h"
#include "renderer/surface/kernel.h"
#include "renderer/surface/ray_span.h"

namespace hsb {

// g where an isolated source's K equals C; cached because the bisection
// behind it is too slow to repeat for every ray.
inline double level_g(KernelKind kind, double isovalue) {
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

// Where the ray enters the source's own level surface g = g_level within
// [lo, hi] (lo itself when it starts inside), or −1.
inline double single_source_entry(const RaySpan& s, double g_level, double lo, double hi) {
  if (s.g_min >= g_level) return -1.0;
  const double half = std::sqrt((g_level - s.g_min) / s.a);
  if (s.t_c + half < lo) return -1.0;
  const double t = std::max(s.t_c - half, lo);
  return t <= hi ? t : -1.0;
}

// The level of g_e (the span's quadratic, the bounding ellipsoid's) inside
// which source i's own g is at most g_level, whatever its shape: the
// ellipsoid's own level, and for another shape that of the ball it holds.
// Every shape's u is at most Lσ times √g_e (glyph_shape.h: N ≤ |q| for
// α, β ≤ 1, a signed glyph's cones at most L|q|, and |q| = σ√g_e), so
// g_e ≤ g_level/(Lσ)² puts g ≤ g_level. That ball touches the glyph at the
// ends of its axes: a ray entering it enters the glyph's own level surface
// too, and so F ≥ C, without evaluating the shape.
inline double inner_level_g(const BlobField& field, std::uint32_t i, double g_level) {
  if (shape_is_quadric(field.shape)) return g_level;
  const ShapeParams& shape = field.shapes[i];
  const double reach = double(shape.bound_scale) * double(shape.lipschitz);
  return g_level / (reach * reach);
}

}  // namespace hsb
