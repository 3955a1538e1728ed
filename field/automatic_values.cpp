#include "field/automatic_values.h"

#include <algorithm>
#include <cmath>

namespace hsb {
namespace {

// The reference glyph size as a fraction of D, and the percentile of the
// mapped magnitudes that is drawn at that size.
constexpr double kMagnitudeGlyph = 1.0 / 50.0;
constexpr double kFixedGlyph = 1.0 / 100.0;
// The same as a fraction of the gap between glyphs at data points.
constexpr double kMagnitudeGap = 0.45;
constexpr double kFixedGap = 0.3;
constexpr double kReferencePercentile = 0.9;
constexpr double kCeilingOverReference = 3.0;
constexpr double kFloorUnderReference = 1.0 / 20.0;
constexpr double kFloorOnLines = 1.0 / 8.0;
// Evenly spaced seeding: the body's measure over the separation's cube
// (square, length).
constexpr double kLinesAcrossVolume = 150.0;
constexpr double kLinesAcrossArea = 200.0;
constexpr double kSeedsAlongLine = 20.0;

bool maps_magnitude(RadiusMapping mapping) {
  return mapping == RadiusMapping::linear || mapping == RadiusMapping::sqrt;
}

// The largest radius a glyph gets at scale 1, before floor and ceiling.
double unit_scale_largest_radius(const Vec3& eigenvalues, RadiusMapping mapping) {
  GlyphMapping unit;
  unit.mapping = mapping;
  unit.scale = 1.0;
  unit.floor = 0.0;
  return map_radii(eigenvalues, unit).maxCoeff();
}

}  // namespace

double automatic_step(const Box3& domain, std::optional<double> separation) {
  const double step = domain.diagonal() / 400.0;
  return separation ? std::min(step, *separation / 10.0) : step;
}
double automatic_max_length(const Box3& domain) { return 2.0 * domain.diagonal(); }
double automatic_spacing(const Box3& domain, RadiusMapping mapping, std::optional<double> separation) {
  const bool by_magnitude = maps_magnitude(mapping);
  if (separation) {
    const double gap = line_gap(*separation);
    return by_magnitude ? 1.25 * kMagnitudeGap * gap : 4.0 * kFixedGap * gap;
  }
  return domain.diagonal() / (by_magnitude ? 40.0 : 25.0);
}

double automatic_separation(const BodyLattice& body) {
  switch (body.dimensions) {
    case 3: return std::cbrt(body.measure / kLinesAcrossVolume);
    case 2: return std::sqrt(body.measure / kLinesAcrossArea);
    default: return body.measure / kSeedsAlongLine;
  }
}

double line_gap(double separation) { return 2.0 / 3.0 * separation; }

SeedSpec automatic_seeds(const Box3& domain, std::optional<int> plane_axis) {
  Eigen::Index longest = 0;
  domain.size().maxCoeff(&longest);
  if (plane_axis) longest = *plane_axis;  // the grid across the normal is the plane
  const Eigen::Index u = (longest + 1) % 3, v = (longest + 2) % 3;
  SeedGridSpec grid;
  grid.corner = Vec3::Zero();
  grid.corner[longest] = 0.5;
  grid.edge_u = Vec3::Unit(u);
  grid.edge_v = Vec3::Unit(v);
  grid.n = grid.m = 5;
  SeedSpec seeds;
  seeds.grids.push_back(grid);
  seeds.frame = SeedFrame::bounds;
  return seeds;
}

int automatic_stride(std::size_t sites) { return int(std::max<std::size_t>(1, (sites + 19999) / 20000)); }

double site_gap(const Box3& domain, std::size_t count) {
  const double d = domain.diagonal();
  double measure = 1.0;
  int dimensions = 0;
  for (int k = 0; k < 3; ++k)
    if (domain.size()[k] > 1e-6 * d) measure *= domain.size()[k], ++dimensions;
  if (dimensions == 0 || count < 2) return d > 0.0 ? d : 1.0;
  return std::pow(measure / double(count), 1.0 / dimensions);
}

GlyphMapping automatic_glyph_mapping(const GlyphSizeSpec& spec, const std::vector<Vec3>& eigenvalues,
                                     const Box3& domain, double glyph_extent, std::optional<double> gap, bool lines) {
  const bool by_magnitude = maps_magnitude(spec.mapping);
  const double reference_size = gap ? *gap * (by_magnitude ? kMagnitudeGap : kFixedGap)
                                    : domain.diagonal() * (by_magnitude ? kMagnitudeGlyph : kFixedGlyph);

  double reference_radius = 1.0;  // at scale 1
  if (by_magnitude) {
    std::vector<double> radii;
    radii.reserve(eigenvalues.size());
    for (const Vec3& l : eigenvalues) {
      const double r = unit_scale_largest_radius(l, spec.mapping);
      if (r > 0.0 && std::isfinite(r)) radii.push_back(r);
    }
    if (!radii.empty()) {
      const auto k = std::size_t(kReferencePercentile * double(radii.size() - 1) + 0.5);
      std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(k), radii.end());
      reference_radius = radii[k];
    }
  }

  GlyphMapping m;
  m.mapping = spec.mapping;
  m.scale = spec.scale.value_or(reference_size / (glyph_extent * reference_radius));
  // Floor and ceiling follow the reference glyph at the scale in use, so
  // a pinned scale keeps its picture: in radii, the reference is this.
  const double reference = m.scale * reference_radius;
  m.ceiling = spec.ceiling.value_or(kCeilingOverReference * reference);
  m.floor = spec.floor.value_or((lines ? kFloorOnLines : kFloorUnderReference) * std::min(reference, m.ceiling));
  // A pinned floor above the automatic ceiling wins: the user asked for it.
  if (!spec.ceiling) m.ceiling = std::max(m.ceiling, m.floor);
  return m;
}

}  // namespace hsb
