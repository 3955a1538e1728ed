#pragma once
// Which way round a data set's signs are: mechanics writes tension as
// positive stress, geomechanics (soil and rock, where almost everything is
// compressed) writes compression as positive. What shows tension and
// compression (the signed glyph's points, the colour map's ends, the
// legend's words) asks this instead of the sign itself.

namespace hsb {

enum class SignConvention {
  tension_positive,     // mechanics (the default): σ > 0 pulls
  compression_positive  // geomechanics: σ > 0 pushes
};

// Whether an eigenvalue (or any normal stress) of this sign compresses.
inline bool is_compressive(double value, SignConvention sign) {
  return sign == SignConvention::tension_positive ? value < 0.0 : value > 0.0;
}

}  // namespace hsb
