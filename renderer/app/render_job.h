#pragma once
// One scene file rendered to one image: the whole data flow of design §4.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "renderer/app/progress.h"
#include "renderer/scene/scene_spec.h"
#include "renderer/surface/trace_stats.h"

namespace hsb {

struct RenderJob {
  std::string scene_path;
  std::vector<std::string> overrides;  // --set key=value
  std::string output_dir = "out";
  // A sweep's values ("glyphs.spacing=0.02"), appended to the image's name.
  std::string variant;
  // Render only when the image there does not hold this scene's hash
  // (scene text, overrides and data file): a re-run batch renders what
  // changed.
  bool skip_existing = false;
  // Told each stage and, while rendering, the fraction done.
  std::function<void(JobStage, double)> progress;
  // The images this batch has written so far, each with the scene that
  // wrote it: a second scene with the same image name is refused before it
  // renders rather than overwriting the first. Null: no check.
  std::map<std::string, std::string>* written = nullptr;
};

struct RenderSummary {
  std::string image_path;
  bool skipped = false;  // skip_existing found it up to date
  std::size_t trajectories = 0;
  std::size_t sources = 0;
  double build_seconds = 0.0;   // data set, trajectories, sources, BVH
  double render_seconds = 0.0;  // rays and shading
  double output_seconds = 0.0;  // colour management, colour bar, encoding and writing
  double total_seconds = 0.0;
  std::uint64_t primary_rays = 0, shadow_rays = 0;
  double primary_mrays_per_second = 0.0, shadow_mrays_per_second = 0.0;
  TraceStats stats, shadow_stats;  // camera rays; shadow and occlusion rays
  std::vector<std::string> warnings;  // about the data; the image is still complete
  double memory_estimate = 0.0;       // PreparedScene::memory_estimate
};

// Renders `job` and writes the image. Throws SceneError for bad scene input
// and std::runtime_error for anything else that prevents a complete image;
// no partial image is ever left behind.
RenderSummary run_render_job(const RenderJob& job);

}  // namespace hsb
