#pragma once
// Metaball sources placed along trajectories: the field library's output.

#include <vector>

#include "field/glyph_mapping.h"
#include "field/tensor_field.h"
#include "field/trajectory.h"

namespace hsb {

// One anisotropic metaball source (paper eq. 11): centre, principal axes
// (columns, right-handed), radii along them and the colour scalar. The
// renderer turns this into its shape matrix; this library never renders.
struct GlyphSource {
  Vec3 centre = Vec3::Zero();
  Mat3 axes = Mat3::Identity();
  Vec3 radii = Vec3::Ones();
  Vec3 eigenvalues = Vec3::Zero();
  double scalar = 0.0;
};

// How many sources place_sources() puts along `trajectory` at `spacing`
// (some may then be skipped where the field cannot be sampled).
std::size_t source_count(const Trajectory& trajectory, double spacing);

// Sources at arc-length `spacing` along `trajectory` (the paper's sample
// ratio), the run of them centred on the curve's length. Each takes the
// tensor sampled at its centre; points where the field cannot be sampled
// are skipped. Radii are left for size_sources(), once the mapping is
// known: its automatic scale depends on all the sources' eigenvalues.
std::vector<GlyphSource> place_sources(const TensorField& field, const Trajectory& trajectory,
                                       double spacing, ColorScalar color);

// A source for one tensor at one point, radii not yet set.
GlyphSource make_source(const Vec3& centre, const Sym3& tensor, ColorScalar color);
// The same with radii (discrete glyphs, tests).
GlyphSource make_source(const Vec3& centre, const Sym3& tensor, const GlyphMapping& mapping,
                        ColorScalar color);

// Sets every source's radii from its eigenvalues.
void size_sources(std::vector<GlyphSource>& sources, const GlyphMapping& mapping);

}  // namespace hsb
