#pragma once
// Display-referred floats quantised to 8 bits without banding: a smooth
// gradient spans only 256 levels, and plain rounding draws its steps as
// contours on a shaded glyph. Each colour value gets a different fraction
// of a level added before it is truncated, from interleaved gradient
// noise (Jimenez, "Next generation post processing in Call of Duty:
// Advanced Warfare", SIGGRAPH 2014): a pattern without low frequencies,
// so the error shows as fine grain, and whose average over a neighbourhood
// is the exact value.

#include <vector>

namespace hsb {

// `pixels` (width × height × channels, top row first, values in [0, 1];
// outside is clamped) as bytes, dithered; the channel `alpha_channel`
// (none when < 0) is rounded, not dithered, so an opaque pixel stays 255.
// Each byte depends only on its own value and position: bands of rows on
// every core give the bytes one core gives.
std::vector<unsigned char> dithered_8bit(const std::vector<float>& pixels, int width, int height, int channels,
                                         int alpha_channel);

// The dither's fraction of a level at pixel (x, y) for channel c, in [0, 1).
float dither_offset(int x, int y, int c);

}  // namespace hsb
