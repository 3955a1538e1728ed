#pragma once
// A scene's trajectories and sources written for other tools (hsb export).

#include <string>
#include <vector>

namespace hsb {

struct ExportJob {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string output_dir = "out";
};

// Writes <scene stem>_trajectories.vtp and <scene stem>_sources.vtp into the
// output folder and returns their paths. The sources' "glyph" tensors are
// scaled so that ParaView's Tensor Glyph draws each source as the ellipsoid
// it is when isolated in this renderer (R·r_k times the kernel's level
// radius for the isovalue).
std::vector<std::string> run_export_job(const ExportJob& job);

}  // namespace hsb
