#pragma once
// Sources along a curve given by the scene, with one fixed shape and size:
// the method itself shown without data (the paper's Figures 2 and 3:
// ellipsoids along a curve that blend into a tube as their number grows).

#include <vector>

#include "field/glyphs/glyph_sources.h"
#include "field/tracing/trajectory.h"

namespace hsb {

enum class CurveKind { line, circle, helix, polyline };

struct CurveSpec {
  CurveKind kind = CurveKind::helix;
  Vec3 from = Vec3::Zero(), to = Vec3::UnitX();  // line
  Vec3 centre = Vec3::Zero();                    // circle, helix: the centre (helix: of its bottom turn)
  double radius = 1.0;                           // circle, helix
  Vec3 axis = Vec3::UnitZ();                     // circle: its normal; helix: its axis
  double pitch = 1.0;                            // helix: rise per turn
  double turns = 2.0;                            // helix: turns (circle: always one, closed)
  std::vector<Vec3> points;                      // polyline, at least two
  int count = 12;                                // sources, evenly spaced by arc length
  // An isolated glyph's semi-axes, in the scene's units: the first along
  // the curve, the second towards the curve's centre of turning (or a fixed
  // side for a straight curve), the third across both.
  Vec3 semi_axes{0.3, 0.1, 0.1};
};

// The curve as a polyline, fine enough to draw and to space sources along.
Trajectory curve_points(const CurveSpec& spec);

// `count` sources evenly spaced by arc length along the curve, the ends
// included (a circle's first and last do not coincide), each with radii
// semi_axes / glyph_extent (so that alone it is the ellipsoid of
// semi_axes) and its arc-length fraction, 0 to 1, as colour scalar.
std::vector<GlyphSource> curve_sources(const CurveSpec& spec, double glyph_extent);

}  // namespace hsb
