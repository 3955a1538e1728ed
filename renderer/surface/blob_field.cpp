#include "renderer/surface/blob_field.h"

#include <algorithm>
#include <stdexcept>

namespace hsb {

BlobSource make_blob_source(const Vec3& centre, const Mat3& axes, const Vec3& radii,
                            double influence_radius, const std::array<float, 3>& color, double scalar) {
  BlobSource s{};
  for (int k = 0; k < 3; ++k) {
    const double inv = 1.0 / (influence_radius * radii[k]);
    for (int j = 0; j < 3; ++j) s.w[3 * k + j] = static_cast<float>(axes(j, k) * inv);
    s.centre[k] = static_cast<float>(centre[k]);
  }
  s.color = color;
  s.scalar = float(scalar);
  return s;
}

BlobField make_blob_field(const std::vector<GlyphSource>& glyphs,
                          const std::vector<std::array<float, 3>>& colors,
                          double influence_radius, KernelKind kernel, Blend blend,
                          double isovalue, GlyphShape shape, double sharpness, SignConvention sign) {
  if (colors.size() != glyphs.size())
    throw std::invalid_argument("make_blob_field: one colour per glyph is required");
  BlobField field;
  field.kernel = kernel;
  field.blend = blend;
  field.isovalue = isovalue;
  field.shape = shape;
  if (shape != GlyphShape::ellipsoid) {
    std::vector<Vec3> radii, eigenvalues;
    for (const GlyphSource& g : glyphs) radii.push_back(g.radii), eigenvalues.push_back(g.eigenvalues);
    field.shapes = shape_params(shape, radii, eigenvalues, sharpness, sign);
  }
  field.sources.reserve(glyphs.size());
  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    // W_s = W/σ: the bounding ellipsoid's radii are σ R r_k.
    const double sigma = shape == GlyphShape::ellipsoid ? 1.0 : double(field.shapes[i].bound_scale);
    field.sources.push_back(make_blob_source(glyphs[i].centre, glyphs[i].axes, glyphs[i].radii,
                                             sigma * influence_radius, colors[i], glyphs[i].scalar));
  }
  const auto differs = [&](const GlyphSource& g) { return g.group != glyphs.front().group; };
  if (std::any_of(glyphs.begin(), glyphs.end(), differs))
    for (const GlyphSource& g : glyphs) field.groups.push_back(g.group);
  return field;
}

Box3 influence_bounds(const BlobField& field, std::size_t i) {
  // The ellipsoid's semi-axis k is row k of W_s divided by its squared
  // length (W_s's rows are orthogonal), so its half-extent along world
  // axis j is the length of the j-th components of those semi-axis
  // vectors. A superquadric's point x = c + Σ_k q_k semi-axis_k / σ (q in
  // its own frame) has x_j − c_j = a·q / σ, a_k the j-th component of
  // semi-axis k: its support reaches superquadric_reach(a) / σ, the
  // support's own extent, where the cube and cylinder that hold it (up to
  // √3 times the glyph along an aslant diagonal) overshoot.
  const BlobSource& s = field.sources[i];
  Vec3 semi_axes[3], ellipsoid = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    const Vec3 row(s.w[3 * k], s.w[3 * k + 1], s.w[3 * k + 2]);
    semi_axes[k] = row / row.squaredNorm();
    ellipsoid += semi_axes[k].cwiseAbs2();
  }
  Vec3 half = ellipsoid.cwiseSqrt();
  if (!shape_is_quadric(field.shape)) {
    const ShapeParams& shape = field.shapes[i];
    const double sigma = double(shape.bound_scale);
    for (int j = 0; j < 3; ++j) {
      const Vec3 a(semi_axes[0][j], semi_axes[1][j], semi_axes[2][j]);
      half[j] = std::min(half[j], superquadric_reach(shape, a) / sigma);
    }
    // A signed glyph's double cone about each axis k with points
    // (glyph_shape.h: C_k ≤ u) is the hull of its apexes ±semi-axis k and
    // its base, the circle of radius ρ across k: along world axis j it
    // reaches the larger of the apex's component and ρ times the base's.
    // Under the point load, glyphs compressed every way lie aslant, and
    // the superquadric's corners stick out far past the cones' sides.
    for (int k = 0; k < 3; ++k) {
      if (!(shape.pointed & (1u << k))) continue;
      const int i1 = (k + 1) % 3, j1 = (k + 2) % 3;
      const Vec3 across_k = (semi_axes[i1].cwiseAbs2() + semi_axes[j1].cwiseAbs2()).cwiseSqrt();
      const Vec3 bicone = semi_axes[k].cwiseAbs().cwiseMax(kConeBase * across_k);
      half = half.cwiseMin((1.0 + 1e-6) * bicone / sigma);  // rounded up, as the reach
    }
  }
  const Vec3 c(s.centre[0], s.centre[1], s.centre[2]);
  return {c - half, c + half};
}

Box3 influence_bounds(const BlobField& field) {
  if (field.sources.empty()) return {};
  Box3 all = influence_bounds(field, 0);
  for (std::size_t i = 1; i < field.sources.size(); ++i) all.extend(influence_bounds(field, i));
  return all;
}

double source_g(const BlobField& field, std::size_t i, const Vec3& x) {
  const BlobSource& s = field.sources[i];
  return shape_g(field.shape, shape_params(field, i), scaled_offset(s, shape_matrix(s), x));
}

std::vector<std::uint8_t> field_groups(const BlobField& field) {
  if (field.groups.empty()) return {0};
  std::vector<std::uint8_t> groups = field.groups;
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  return groups;
}

double field_value(const BlobField& field, const Vec3& x) {
  // Each group's own F; the union's is the largest (its level set is the
  // union of theirs).
  std::array<double, 256> f{};
  for (std::size_t i = 0; i < field.sources.size(); ++i) {
    const double k = kernel_value(field.kernel, source_g(field, i, x));
    double& group = f[field.groups.empty() ? 0 : field.groups[i]];
    group = blended(field.blend, group, k);
  }
  return *std::max_element(f.begin(), f.end());
}

}  // namespace hsb
