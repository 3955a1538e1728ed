#include "field/glyphs/curve_sources.h"

#include <algorithm>
#include <cmath>

namespace hsb {
namespace {

// Segments of a circle or helix turn: fine enough that the polyline's
// length is the curve's to 1e-4.
constexpr int kSegmentsPerTurn = 256;

// Two unit vectors spanning the plane across `axis`.
void plane_across(const Vec3& axis, Vec3& u, Vec3& v) {
  const Vec3 a = axis.normalized();
  const Vec3 helper = std::fabs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  u = a.cross(helper).normalized();
  v = a.cross(u);
}

// The point at arc length `s` along `points` (cumulative lengths in
// `lengths`), and the direction there.
void along(const std::vector<Vec3>& points, const std::vector<double>& lengths, double s, Vec3& at, Vec3& tangent) {
  std::size_t i = 1;
  while (i + 1 < points.size() && lengths[i] < s) ++i;
  const double segment = lengths[i] - lengths[i - 1];
  const double t = segment > 0.0 ? std::clamp((s - lengths[i - 1]) / segment, 0.0, 1.0) : 0.0;
  at = points[i - 1] + t * (points[i] - points[i - 1]);
  tangent = (points[i] - points[i - 1]).normalized();
}

}  // namespace

Trajectory curve_points(const CurveSpec& c) {
  Trajectory curve;
  std::vector<Vec3>& p = curve.points;
  Vec3 u, v;
  switch (c.kind) {
    case CurveKind::line:
      p = {c.from, c.to};
      break;
    case CurveKind::polyline:
      p = c.points;
      break;
    case CurveKind::circle:
      plane_across(c.axis, u, v);
      for (int i = 0; i <= kSegmentsPerTurn; ++i) {
        const double a = 2.0 * M_PI * i / kSegmentsPerTurn;
        p.push_back(c.centre + c.radius * (std::cos(a) * u + std::sin(a) * v));
      }
      break;
    case CurveKind::helix: {
      plane_across(c.axis, u, v);
      const Vec3 a = c.axis.normalized();
      const int n = std::max(2, int(std::ceil(kSegmentsPerTurn * c.turns)));
      for (int i = 0; i <= n; ++i) {
        const double t = c.turns * double(i) / n;  // in turns
        const double angle = 2.0 * M_PI * t;
        p.push_back(c.centre + c.radius * (std::cos(angle) * u + std::sin(angle) * v) + c.pitch * t * a);
      }
      break;
    }
  }
  curve.forward_stop = curve.backward_stop = c.kind == CurveKind::circle ? StopReason::closed : StopReason::max_length;
  return curve;
}

std::vector<GlyphSource> curve_sources(const CurveSpec& spec, double glyph_extent) {
  const Trajectory curve = curve_points(spec);
  const std::vector<Vec3>& p = curve.points;
  std::vector<double> lengths{0.0};
  for (std::size_t i = 1; i < p.size(); ++i) lengths.push_back(lengths.back() + (p[i] - p[i - 1]).norm());
  const double total = lengths.back();
  const bool closed = spec.kind == CurveKind::circle;
  const int n = std::max(1, spec.count);
  // For a straight curve the second axis has no natural side: the one
  // nearest the world's z (or y, along z).
  const Vec3 chord = (p.back() - p.front()).normalized();
  std::vector<GlyphSource> sources;
  for (int i = 0; i < n; ++i) {
    const double fraction = n == 1 ? 0.5 : closed ? double(i) / n : double(i) / (n - 1);
    Vec3 at, tangent;
    along(p, lengths, fraction * total, at, tangent);
    // Towards the centre of turning: the change of direction over a short
    // stretch, made perpendicular to the tangent.
    Vec3 before, after, ignored;
    along(p, lengths, std::max(0.0, fraction * total - 0.01 * total), ignored, before);
    along(p, lengths, std::min(total, fraction * total + 0.01 * total), ignored, after);
    Vec3 normal = after - before;
    normal -= normal.dot(tangent) * tangent;
    if (normal.norm() < 1e-6) {
      const Vec3 up = std::fabs(chord.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitY();
      normal = up - up.dot(tangent) * tangent;
    }
    normal.normalize();
    GlyphSource s;
    s.centre = at;
    s.axes.col(0) = tangent;
    s.axes.col(1) = normal;
    s.axes.col(2) = tangent.cross(normal);
    s.eigenvalues = spec.semi_axes;
    s.radii = spec.semi_axes / glyph_extent;
    s.scalar = fraction;
    sources.push_back(s);
  }
  return sources;
}

}  // namespace hsb
