#pragma once
// Metaball sources placed along trajectories: the field library's output.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "field/glyphs/glyph_mapping.h"
#include "field/sampling/field.h"
#include "field/tracing/trajectory.h"

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
  // The surface it blends into: sources of one group blend, and the
  // groups' surfaces stand side by side (a union). A line family's
  // sources are a group of their own (the family's axis), so tension
  // lines cross compression lines instead of melting into them.
  std::uint8_t group = 0;
};

// How many sources place_sources() puts along `trajectory` at `spacing`
// (some may then be skipped where the field cannot be sampled). A double:
// a tiny spacing gives counts no integer type holds, and the memory check
// must see them as they are.
double source_count(const Trajectory& trajectory, double spacing);

// The source a field makes at a point, radii not yet set; nothing where
// the field cannot be sampled.
using SourceMaker = std::function<std::optional<GlyphSource>(const Vec3&)>;

// Sources at arc-length `spacing` along `trajectory` (the paper's sample
// ratio), the run of them centred on the curve's length, each made by
// `make` at its centre; points where it makes none are skipped. Radii are
// left for size_sources(), once the mapping is known: its automatic scale
// depends on all the sources' eigenvalues.
std::vector<GlyphSource> place_sources(const Trajectory& trajectory, double spacing, const SourceMaker& make);
// Glyphs end to end along a trajectory, as beads on a string, instead of
// at a fixed spacing: each next centre where the two glyphs alone overlap
// by `overlap` of their lengths along the line (0: tip touches tip), so a
// glyph's end shows: flat ends butted together, points meeting points.
struct BeadRule {
  double overlap = 0.0;  // below 0: a gap of that fraction
  // A made source's extent along the line from its centre (its radius
  // along the followed axis, as a length).
  std::function<double(const GlyphSource&)> half_length;
  // The walk's least step, and its step where no source can be made.
  double least_step = 1.0;
};
// The beads along `trajectory`, each made by `make` at its centre, the run
// centred on the curve.
std::vector<GlyphSource> place_beads(const Trajectory& trajectory, const BeadRule& rule, const SourceMaker& make);

// The same with the tensor sampled at each centre.
std::vector<GlyphSource> place_sources(const TensorField& field, const Trajectory& trajectory,
                                       double spacing, ColorScalar color);

// A source for one tensor at one point, radii not yet set.
GlyphSource make_source(const Vec3& centre, const Sym3& tensor, ColorScalar color);
// The same with radii (discrete glyphs, tests).
GlyphSource make_source(const Vec3& centre, const Sym3& tensor, const GlyphMapping& mapping,
                        ColorScalar color);

// A streamball: a flow source at `centre` for velocity `velocity`, its
// first axis along the flow, its three "eigenvalues" the speed (a sphere
// under every mapping; stretch_sources() may elongate it).
GlyphSource make_flow_source(const Vec3& centre, const Vec3& velocity, ColorScalar color);

// Lengthens every source's first radius by `factor` (flow sources: along
// the flow), after sizing.
void stretch_sources(std::vector<GlyphSource>& sources, double factor);

// 2-D data: every source's radius along `normal` (along its axis nearest
// it: for planar tensors, the medium one) set to `half_thickness`, or, when
// none is given, to its smaller in-plane radius: lenses lying in the plane.
void flatten_sources(std::vector<GlyphSource>& sources, const Vec3& normal, std::optional<double> half_thickness);

// Sets every source's radii from its eigenvalues.
void size_sources(std::vector<GlyphSource>& sources, const GlyphMapping& mapping);

}  // namespace hsb
