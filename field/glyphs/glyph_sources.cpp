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

namespace {

// Points of a polyline by arc length.
class ArcLength {
 public:
  explicit ArcLength(const std::vector<Vec3>& points) : pts_(points), start_(points.size(), 0.0) {
    for (std::size_t i = 1; i < pts_.size(); ++i) start_[i] = start_[i - 1] + (pts_[i] - pts_[i - 1]).norm();
  }
  Vec3 at(double s) const {
    if (pts_.size() < 2 || s <= 0.0) return pts_.front();
    // The segment that ends at or after s (the earlier one where s is a
    // point's own arc length).
    const std::size_t end = std::size_t(std::lower_bound(start_.begin(), start_.end(), s) - start_.begin());
    if (end >= pts_.size()) return pts_.back();
    const std::size_t i = end - 1;
    const double length = (pts_[i + 1] - pts_[i]).norm();
    const double t = length > 0.0 ? (s - start_[i]) / length : 0.0;
    return pts_[i] + std::max(0.0, t) * (pts_[i + 1] - pts_[i]);
  }

 private:
  const std::vector<Vec3>& pts_;
  std::vector<double> start_;  // the arc length at each point
};

}  // namespace

std::vector<GlyphSource> place_sources(const Trajectory& trajectory, double spacing, const SourceMaker& make) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw std::invalid_argument("glyph sources: spacing must be finite and > 0");
  std::vector<GlyphSource> sources;
  if (trajectory.points.empty()) return sources;

  // As many sources as fit at `spacing`, the run centred on the curve so
  // both ends look alike; round a loop, the whole number nearest its
  // length over `spacing`, evenly (a source at each end of the seam would
  // swell the blend there).
  const double total = trajectory.length();
  // The caller has checked the count against memory, so it fits.
  std::size_t count = static_cast<std::size_t>(source_count(trajectory, spacing));
  double first = 0.5 * (total - static_cast<double>(count - 1) * spacing);
  if (trajectory.closed()) {
    count = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(total / spacing)));
    spacing = total / static_cast<double>(count);
    first = 0.0;
  }
  sources.reserve(count);
  const ArcLength curve(trajectory.points);
  for (std::size_t i = 0; i < count; ++i)
    if (std::optional<GlyphSource> s = make(curve.at(first + static_cast<double>(i) * spacing)))
      sources.push_back(std::move(*s));
  return sources;
}

std::vector<GlyphSource> place_beads(const Trajectory& trajectory, const BeadRule& rule, const SourceMaker& make) {
  if (!(rule.overlap > -1.0 && rule.overlap < 1.0) || !(rule.least_step > 0.0))
    throw std::invalid_argument("glyph beads: overlap must be in (-1, 1) and the least step > 0");
  if (trajectory.points.empty()) return {};
  const double total = trajectory.length();
  const ArcLength curve(trajectory.points);
  const auto made_at = [&](double s) { return make(curve.at(s)); };
  const double keep = 1.0 - rule.overlap;
  // The beads from arc length `first` on, and where the last one stands.
  struct Run {
    std::vector<GlyphSource> beads;
    double last = 0.0;
  };
  const auto walk_from = [&](double first) {
    Run run;
    double s = first;
    std::optional<GlyphSource> bead = made_at(s);
    while (s <= total) {
      if (!bead) {  // no glyph here (outside the data): move on and look again
        s += rule.least_step;
        bead = made_at(s);
        continue;
      }
      // The next centre s' solves s' = s + keep (h + h(s')): three rounds
      // of the fixed point from h(s') = h are plenty, as a glyph changes
      // little over its own length.
      const double h = rule.half_length(*bead);
      double step = 2.0 * keep * h;
      for (int round = 0; round < 3; ++round) {
        const std::optional<GlyphSource> next = made_at(s + std::max(step, rule.least_step));
        if (!next) break;
        step = keep * (h + rule.half_length(*next));
      }
      run.beads.push_back(std::move(*bead));
      run.last = s;
      s += std::max(step, rule.least_step);
      bead = made_at(s);
    }
    return run;
  };
  // Centred like place_sources' run: walked again from half the length
  // the first walk left over, so both ends look alike.
  const Run from_start = walk_from(0.0);
  if (from_start.beads.empty()) return {};
  return walk_from(0.5 * (total - from_start.last)).beads;
}

}  // namespace hsb
