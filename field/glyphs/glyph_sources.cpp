#include "field/glyphs/glyph_sources.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "field/tensor/eigensystem.h"

namespace hsb {

GlyphSource make_source(const Vec3& centre, const Sym3& tensor, ColorScalar color) {
  const Eigensystem es = decompose(tensor);
  GlyphSource source;
  source.centre = centre;
  source.axes = es.vectors;
  source.eigenvalues = es.values;
  source.scalar = color_scalar(es.values, color);
  return source;
}

GlyphSource make_source(const Vec3& centre, const Sym3& tensor, const GlyphMapping& mapping,
                        ColorScalar color) {
  GlyphSource source = make_source(centre, tensor, color);
  source.radii = map_radii(source.eigenvalues, mapping);
  return source;
}

void size_sources(std::vector<GlyphSource>& sources, const GlyphMapping& mapping) {
  for (GlyphSource& s : sources) s.radii = map_radii(s.eigenvalues, mapping);
}

double source_count(const Trajectory& trajectory, double spacing) {
  if (trajectory.points.empty()) return 0.0;
  // The epsilon keeps a length that is a whole number of spacings (up to
  // rounding) from losing its last source.
  return std::floor(trajectory.length() / spacing + 1e-9) + 1.0;
}

std::vector<GlyphSource> place_sources(const TensorField& field, const Trajectory& trajectory,
                                       double spacing, ColorScalar color) {
  return place_sources(trajectory, spacing, [&](const Vec3& p) -> std::optional<GlyphSource> {
    const std::optional<Sym3> s = field.sample(p);
    if (!s) return std::nullopt;
    return make_source(p, *s, color);
  });
}

GlyphSource make_flow_source(const Vec3& centre, const Vec3& velocity, ColorScalar color) {
  GlyphSource source;
  source.centre = centre;
  const double speed = velocity.norm();
  // A right-handed frame whose first axis is the flow's direction.
  const Vec3 along = speed > 0.0 ? Vec3(velocity / speed) : Vec3::UnitX();
  const Vec3 helper = std::fabs(along.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 second = along.cross(helper).normalized();
  source.axes.col(0) = along;
  source.axes.col(1) = second;
  source.axes.col(2) = along.cross(second);
  source.eigenvalues = Vec3::Constant(speed);
  source.scalar = color_scalar(source.eigenvalues, color);
  return source;
}

void stretch_sources(std::vector<GlyphSource>& sources, double factor) {
  for (GlyphSource& s : sources) s.radii.x() *= factor;
}

void flatten_sources(std::vector<GlyphSource>& sources, const Vec3& normal, std::optional<double> half_thickness) {
  for (GlyphSource& s : sources) {
    Eigen::Index across = 0;
    (s.axes.transpose() * normal).cwiseAbs().maxCoeff(&across);
    const double in_plane = std::min(s.radii[(across + 1) % 3], s.radii[(across + 2) % 3]);
    s.radii[across] = half_thickness.value_or(in_plane);
  }
}

std::vector<GlyphSource> place_sources(const Trajectory& trajectory, double spacing, const SourceMaker& make) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw std::invalid_argument("glyph sources: spacing must be finite and > 0");
  std::vector<GlyphSource> sources;
  const std::vector<Vec3>& pts = trajectory.points;
  if (pts.empty()) return sources;

  // As many sources as fit at `spacing`, the run centred on the curve so
  // both ends look alike.
  const double total = trajectory.length();
  // The caller has checked the count against memory, so it fits.
  const std::size_t count = static_cast<std::size_t>(source_count(trajectory, spacing));
  const double first = 0.5 * (total - static_cast<double>(count - 1) * spacing);
  sources.reserve(count);

  // Walk the polyline once: arc-length targets only increase.
  std::size_t segment = 0;   // current segment is pts[segment] → pts[segment + 1]
  double segment_start = 0;  // arc length at pts[segment]
  for (std::size_t i = 0; i < count; ++i) {
    const double target = first + static_cast<double>(i) * spacing;
    Vec3 p = pts.back();
    while (segment + 1 < pts.size()) {
      const double seg_len = (pts[segment + 1] - pts[segment]).norm();
      if (target <= segment_start + seg_len) {
        const double t = seg_len > 0.0 ? (target - segment_start) / seg_len : 0.0;
        p = pts[segment] + std::max(0.0, t) * (pts[segment + 1] - pts[segment]);
        break;
      }
      segment_start += seg_len;
      ++segment;
    }
    if (std::optional<GlyphSource> s = make(p)) sources.push_back(std::move(*s));
  }
  return sources;
}

}  // namespace hsb
