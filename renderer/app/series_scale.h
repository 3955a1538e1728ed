#pragma once
// One glyph scale, colour range and frame across the steps of a time series,
// so that a growing load shows as growing glyphs and warming colours, not
// as the same picture with other tick labels. Each step is rendered on its
// own (a cluster node may render one step alone), so every step computes
// the same shared settings from all of them and pins them.

#include <functional>
#include <string>
#include <vector>

namespace hsb {

// One step: its scene (or data file) and the --set values that make it.
struct SeriesMember {
  std::string scene;
  std::vector<std::string> overrides;
};

// The --set values that pin what the steps share, for every key the scene
// leaves automatic: glyphs.scale, glyphs.floor and glyphs.ceiling of the
// step with the largest stresses (the smallest automatic scale: no other
// step's glyphs grow past its ceiling), color.map and color.range over
// the glyphs of all steps, by the rules of a single picture, and that
// step's render.width, render.height and camera (its glyphs frame the
// others'), so an animation's frames neither jump nor change size.
// Every step is read, its glyphs sampled on its body's lattice
// (field/glyph_pipeline.h: GlyphPlacing); only the step with the largest
// stresses is traced, and prepared a second time for its picture size and
// camera: once per series, not per image. `progress` hears the fraction of
// the steps read.
// The keys shared_series_settings() may pin.
const std::vector<std::string>& series_pinned_keys();

std::vector<std::string> shared_series_settings(const std::vector<SeriesMember>& members,
                                                const std::function<void(double)>& progress = {});

}  // namespace hsb
