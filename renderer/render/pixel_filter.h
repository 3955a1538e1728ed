#pragma once
// The pixel reconstruction filter: a Blackman–Harris window 3 pixels wide.
// Each sample counts towards every pixel whose centre lies within 1.5
// pixels of it, weighted by the window (separable in x and y). Against a
// box filter it keeps edges crisp without the jagged steps of a staircase,
// and against a Gaussian of the same width it blurs less.

namespace hsb {

constexpr double kFilterRadius = 1.5;  // pixels
// How many pixels around its own a sample reaches.
constexpr int kFilterReach = 2;

// The window at offset (dx, dy) from a pixel's centre, in pixels; zero
// beyond the radius.
double filter_weight(double dx, double dy);

}  // namespace hsb
