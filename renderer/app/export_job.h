#pragma once
// A scene's trajectories and sources written for other tools (hsb export).

#include <string>
#include <vector>

namespace hsb {

enum class ExportFormat {
  vtp,  // trajectories and sources as VTK PolyData, for ParaView
  pov,  // the whole scene for POV-Ray 3.7 (quartic kernel only)
};

struct ExportJob {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string output_dir = "out";
  ExportFormat format = ExportFormat::vtp;
};

// vtp: writes <scene stem>_trajectories.vtp and <scene stem>_sources.vtp;
// the sources' "glyph" tensors are scaled so that ParaView's Tensor Glyph
// draws each source as the ellipsoid it is when isolated in this renderer
// (R·r_k times the kernel's level radius for the isovalue).
// pov: writes <scene stem>.pov and <scene stem>.ini (which renders to
// <scene stem>.povray.png in the same folder).
// Returns the paths written.
std::vector<std::string> run_export_job(const ExportJob& job);

}  // namespace hsb
