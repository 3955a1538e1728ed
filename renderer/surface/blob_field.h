#pragma once
// The renderer's view of the sources: a blended implicit field
// F(x) = Σ K(g_i(x))  (or max K) whose level set F = C is the surface.

#include <array>
#include <cstdint>
#include <vector>

#include "base/box3.h"
#include "field/glyphs/glyph_sources.h"
#include "renderer/surface/glyph_shape.h"
#include "renderer/surface/kernel.h"

namespace hsb {

enum class Blend { sum, max };

// F so far with one more source's value k: the sum, or for a union the max.
inline double blended(Blend blend, double f, double k) { return blend == Blend::sum ? f + k : (f > k ? f : k); }

// One anisotropic metaball (paper eq. 11). The shape is stored as the matrix
// W = diag(1/(R r_k)) Vᵀ, so that g(x) = |W (x − c)|² = (x − c)ᵀ M (x − c)
// with M = WᵀW. Each row of W is a scaled unit vector, so single precision
// keeps every axis accurate however thin the glyph; storing M itself would
// lose the long axes of needles (M's condition number is the square of the
// glyph's aspect ratio). One source per cache line: a ray tests sources in
// no particular memory order, and a record across two lines would be read
// twice as often.
struct alignas(64) BlobSource {
  std::array<float, 9> w;       // rows of W
  std::array<float, 3> centre;
  std::array<float, 3> color;   // scene-linear RGB
  float scalar = 0.0f;          // the colour scalar, for the film's scalar plane
};
static_assert(sizeof(BlobSource) == 64, "one source per cache line");

struct BlobField {
  std::vector<BlobSource> sources;
  // Each source's group (GlyphSource::group), where there are several:
  // F is summed within a group, and the surface is the union of the
  // groups' own level sets (FieldRay::first_crossing). Empty: one group,
  // every source blends with every other.
  std::vector<std::uint8_t> groups;
  // The sources' shape (glyph_shape.h): their W is the bounding ellipsoid's,
  // and `shapes` holds each one's parameters (empty for ellipsoids).
  GlyphShape shape = GlyphShape::ellipsoid;
  std::vector<ShapeParams> shapes;
  KernelKind kernel = KernelKind::wyvill;
  Blend blend = Blend::sum;
  double isovalue = 0.5;
};

// Sources from the field library's glyphs with the fixed influence radius R
// (paper §4.2) and one scene-linear colour per glyph, in `shape` (with
// `sharpness` for superquadrics, and `sign` telling a signed glyph which
// eigenvalues compress).
BlobField make_blob_field(const std::vector<GlyphSource>& glyphs,
                          const std::vector<std::array<float, 3>>& colors,
                          double influence_radius, KernelKind kernel, Blend blend,
                          double isovalue, GlyphShape shape = GlyphShape::ellipsoid, double sharpness = 3.0,
                          SignConvention sign = SignConvention::tension_positive);

// The groups among the sources (BlobField::groups), in ascending order;
// {0} where there are none.
std::vector<std::uint8_t> field_groups(const BlobField& field);

// Source i's shape parameters: the defaults (σ = 1) for ellipsoids, which
// store none.
inline const ShapeParams& shape_params(const BlobField& field, std::size_t i) {
  static const ShapeParams none;
  return field.shapes.empty() ? none : field.shapes[i];
}

// Source i's g at x, whatever the shape.
double source_g(const BlobField& field, std::size_t i, const Vec3& x);

BlobSource make_blob_source(const Vec3& centre, const Mat3& axes, const Vec3& radii,
                            double influence_radius, const std::array<float, 3>& color, double scalar = 0.0);

// W as a matrix, and W (x − c): the point in the source's scaled frame,
// where g(x) is its squared length. Inline: returned from a call, the
// matrix went through the stack and was read back in pieces other than
// those it was stored in (a store-forwarding stall that held up the
// shading of every hit).
inline Mat3 shape_matrix(const BlobSource& s) {
  Mat3 w;
  for (int i = 0; i < 9; ++i) w(i / 3, i % 3) = s.w[std::size_t(i)];
  return w;
}
inline Vec3 scaled_offset(const BlobSource& s, const Mat3& w, const Vec3& x) {
  return w * (x - Vec3(s.centre[0], s.centre[1], s.centre[2]));
}

// An axis-aligned box holding source i's influence: the box of its
// bounding ellipsoid g_e ≤ 1, narrowed to its shape's support's own box
// (superquadric_reach, glyph_shape.h) and a signed glyph's to its double
// cones' boxes, wherever they are tighter: up to √3 times for a sharp
// glyph aslant, never for the ellipsoid itself. A span the tracer collects
// is narrowed to it (narrow_to_influence, ray_span.h).
Box3 influence_bounds(const BlobField& field, std::size_t i);

// Union of all sources' influence bounds.
Box3 influence_bounds(const BlobField& field);

// F(x) straight from the definition (tests, and whether the camera
// stands inside the surface; rays use ray_spans.h); with groups, the
// largest group's F.
double field_value(const BlobField& field, const Vec3& x);

}  // namespace hsb
