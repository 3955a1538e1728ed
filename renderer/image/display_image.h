#pragma once
// The film's colour made display-referred: what a screen or a printer is
// given. Colour stays premultiplied by alpha; the display transform itself
// works on unpremultiplied colour.

#include <vector>

#include "renderer/image/color_management.h"
#include "renderer/render/film.h"

namespace hsb {

// RGBA, display-referred, premultiplied, top row first. Without
// `keep_alpha` the picture is opaque (the background is part of it). The
// film's colour plane becomes the image, widened where it stands (the film
// reserved its room), so a picture's colour is not held twice: 64 MB less
// at 2000².
std::vector<float> display_pixels(Film&& film, const ColorManagement& color, bool keep_alpha);

// The same for the film's rows [first, last), which it holds (a band of a
// picture written as it is made): (last − first) × width pixels into
// `rgba`, resized to fit, keeping its capacity (the next band reuses it).
void display_rows(const Film& film, int first, int last, const ColorManagement& color, bool keep_alpha,
                  std::vector<float>& rgba);

// The grey of text drawn over `rgba` near (x, y): black over light
// pixels, white over dark ones, black over transparent ones.
float ink_over(const std::vector<float>& rgba, int width, int x, int y);

}  // namespace hsb
