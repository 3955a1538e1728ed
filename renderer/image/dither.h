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

#include "renderer/image/pixel_rows.h"

namespace hsb {

// `rows` as bytes, dithered, `rows.channels` a pixel; the channel
// `alpha_channel` (none when < 0) is rounded, not dithered, so an opaque
// pixel stays 255. Values outside [0, 1] are clamped, NaN is 0. Each byte
// depends only on its own value and its position in the picture: bands of
// rows on every core, or a picture a band at a time, give the bytes one
// core gives for the whole.
// `bytes` is resized to fit, keeping its capacity: a stream's bands reuse
// their buffers instead of taking fresh pages from the system each time.
void dithered_8bit(const PixelRows& rows, int alpha_channel, std::vector<unsigned char>& bytes);

// The dither's fraction of a level at pixel (x, y) for channel c, in [0, 1).
float dither_offset(int x, int y, int c);

}  // namespace hsb
