#pragma once
// The rules for every field-side value a scene may leave automatic. Each is
// a length in the data's own units, taken from the data set's size D (the
// diagonal of its bounding box) or from the tensors themselves, so that a
// data set in millimetres and pascals gets the same picture as one in unit
// cubes. scenes/README.md states the same rules for users.

#include <cstddef>
#include <optional>
#include <vector>

#include "field/glyph_pipeline.h"
#include "field/tracing/body_lattice.h"

namespace hsb {

// RK4 step: D/400, and no more than a tenth of the separation between
// evenly spaced trajectories (`separation`, when they are).
double automatic_step(const Box3& domain, std::optional<double> separation = std::nullopt);
// Trajectory length in each direction from the seed: 2 D (to the boundary).
double automatic_max_length(const Box3& domain);
// Arc length between sources: D/40 for the magnitude mappings, where the
// glyph sizes vary and large ones blend; D/25 for the fixed-size ones, so
// their glyphs stand apart as discrete ellipsoids until the spacing is
// set below about D/40.
// With evenly spaced trajectories `separation` apart, the same in
// proportion to their glyphs (line_gap): 1.25 and 4 reference glyphs.
double automatic_spacing(const Box3& domain, RadiusMapping mapping, std::optional<double> separation = std::nullopt);
// Evenly spaced seeding's separation d_sep, from the body's measure M
// (body_lattice.h; volume in 3-D, area in 2-D): d_sep = (M/150)^(1/3) in
// 3-D, (M/200)^(1/2) in 2-D, M/20 along a line. About 150 lines
// cross a cube (as many cross a thin plate's width as fit 20 across),
// several cross a slender beam's depth, and ~14 a square 2-D result.
double automatic_separation(const BodyLattice& body);
// The room a glyph on one of several lines `separation` apart has, as the
// `gap` automatic_glyph_mapping takes: ⅔ d_sep, so that neighbouring lines'
// reference glyphs (0.3 d_sep) leave 0.4 d_sep of space between them.
double line_gap(double separation);
// A 5×5 grid on the cross-section through the middle of the bounding box,
// across its longest axis (in bounds fractions): trajectories along the
// body of a bar, beam or rail. For a 2-D result (`plane_axis`), a 5×5
// grid over its plane, in the middle of the slab's thickness.
// (seeds.strategy = "grid" without a grid; the default is "even").
SeedSpec automatic_seeds(const Box3& domain, std::optional<int> plane_axis = std::nullopt);

// Glyphs at the data's points (glyphs.placement = "points"): every
// stride-th point, at most 20,000 glyphs (a field of more is a texture,
// not glyphs one can read).
int automatic_stride(std::size_t sites);
// The mean distance between neighbouring glyphs of `count` spread evenly
// over `domain`, in as many dimensions as it has extent (a plane's points
// over its area, a line's along it).
double site_gap(const Box3& domain, std::size_t count);

// The glyph size, for every mapping. Sizes are isolated glyphs' largest
// semi-axes, glyph_extent times the largest radius (see build_glyph_scene).
//  - The reference glyph is G = D/50 for the magnitude mappings (linear,
//    sqrt), D/100 for the fixed-size ones (normalized, constant). For
//    glyphs at data points `gap` apart (site_gap), G = 0.45 gap and
//    0.3 gap: neighbours of the reference size just touch.
//  - scale: a magnitude mapping's reference is the 90th percentile, over
//    all sources, of the mapped largest eigenvalue magnitude: that glyph
//    has size G. At the automatic spacing glyphs of about half that
//    magnitude or more overlap their neighbours along a trajectory and
//    blend; smaller ones stand apart. A fixed-size mapping's glyphs all
//    have size G: separate at the automatic spacing, blended into a
//    hyperstreamline once the spacing is below about D/40.
//  - ceiling: no glyph larger than 3 times the reference (a singular
//    point's neighbourhood would otherwise swallow the picture);
//  - floor: no radius smaller than 1/20 of the reference's (or of the
//    ceiling's, if that is smaller): a flat glyph or a needle stays wide
//    enough to see, a pixel or two, and the glyphs of small stresses
//    shrink to dots, as in the paper's Figure 5. On evenly spaced lines
//    (`lines`), 1/8: a line of uniaxial stress is a needle whose other
//    radii are all floor, and it must read as a tube, not a hairline.
// With a pinned scale, floor and ceiling follow the reference glyph at
// that scale.
// A percentile rather than the maximum, because stress fields have
// singular points whose few extreme values would shrink every other glyph
// to nothing. `eigenvalues` are the sources' (zero tensors are ignored).
GlyphMapping automatic_glyph_mapping(const GlyphSizeSpec& spec, const std::vector<Vec3>& eigenvalues,
                                     const Box3& domain, double glyph_extent,
                                     std::optional<double> gap = std::nullopt, bool lines = false);

}  // namespace hsb
