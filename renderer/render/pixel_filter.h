#pragma once
// The pixel reconstruction filter: a Blackman–Harris window 3 pixels wide.
// Each sample counts towards every pixel whose centre lies within 1.5
// pixels of it, weighted by the window (separable in x and y). Against a
// box filter it keeps edges crisp without the jagged steps of a staircase,
// and against a Gaussian of the same width it blurs less.

namespace hsb {

constexpr double kFilterRadius = 1.5;  // pixels
// How many pixels around its own a sample reaches: a sample lies within its
// pixel, so the centres two pixels away are at least 1.5 pixels from it,
// where the window is zero.
constexpr int kFilterReach = 1;
static_assert(kFilterReach + 0.5 >= kFilterRadius, "the gather reaches every pixel the window does");

// The window's weights of one sample towards the pixels around its own,
// computed once per sample so that a pixel's gather multiplies instead of
// looking the window up 2 × 9 times a sample. x[dx + kFilterReach] is the
// weight towards the pixel dx columns before the sample's (its centre at
// offset dx + sx − ½ from the sample), likewise y by rows; the pixel's
// weight is their product, zero beyond the radius.
struct FilterTaps {
  double x[2 * kFilterReach + 1];
  double y[2 * kFilterReach + 1];
};

// The taps of a sample at (sx, sy) within its pixel, in [0, 1)².
FilterTaps filter_taps(float sx, float sy);

}  // namespace hsb
