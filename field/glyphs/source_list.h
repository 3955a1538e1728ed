#pragma once
// Sources listed in a CSV file, for glyphs computed elsewhere: one row a
// source. A header row names the columns, in any order:
//
//   x, y, z                      the centre (required)
//   r1, r2, r3  or  r            an isolated glyph's semi-axes (or one, a
//                                sphere), in the scene's units (required)
//   ax, ay, az, bx, by, bz       the directions of the first two axes (the
//                                third completes a right-handed frame); or
//   qw, qx, qy, qz               the rotation as a quaternion; or neither:
//                                the axes are x, y, z
//   scalar                       the colour scalar (0 without it)
//
// Blank lines and lines starting with '#' are skipped. Errors name the
// file, line and column, what was expected and what was found.

#include <string>
#include <vector>

#include "field/glyphs/glyph_sources.h"

namespace hsb {

// The sources, radii semi-axes / glyph_extent. Throws DataError.
std::vector<GlyphSource> read_source_list(const std::string& path, double glyph_extent);

}  // namespace hsb
