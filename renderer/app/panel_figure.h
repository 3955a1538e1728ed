#pragma once
// A figure of panels: the scene rendered once per [[panel]] (its keys over
// the scene's), laid out in a grid in one picture, each labelled (a), (b),
// … with an optional caption under them. Panels that colour the same
// scalar with the same map share one colour bar and one range (the
// automatic range then spans all of them); otherwise each keeps its own.
// Each panel goes through the same path as a single picture (its own
// camera framing, anti-aliasing, colour management); the figure is written
// as one PNG, TIFF, PDF or SVG with the scene's metadata.

#include <string>

#include "renderer/app/render_job.h"
#include "renderer/scene/scene_spec.h"

namespace hsb {

RenderSummary render_panel_figure(SceneSpec figure, const std::string& image_path,
                                  const std::function<void(JobStage, double)>& progress);

// How many columns a figure of `panels` panels in a width × height picture
// has: `columns` if given, else the count whose panels are nearest square.
int panel_columns(int panels, int width, int height, std::optional<int> columns);

}  // namespace hsb
