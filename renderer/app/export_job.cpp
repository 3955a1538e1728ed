#include "renderer/app/export_job.h"

#include <filesystem>

#include "field/vtk_export.h"
#include "renderer/scene/scene_spec.h"

namespace hsb {

std::vector<std::string> run_export_job(const ExportJob& job) {
  const SceneSpec spec = load_scene(job.scene_path, job.overrides);
  const GlyphScene glyphs = build_glyph_scene(spec.pipeline);
  const std::filesystem::path dir(job.output_dir);
  std::filesystem::create_directories(dir);
  const std::string stem = std::filesystem::path(job.scene_path).stem().string();
  const std::string trajectories = (dir / (stem + "_trajectories.vtp")).string();
  const std::string sources = (dir / (stem + "_sources.vtp")).string();
  // Tensor Glyph's unit sphere has radius ½.
  const double glyph_scale =
      2.0 * spec.surface.influence_radius * kernel_level_radius(spec.surface.kernel, spec.surface.isovalue);
  write_glyph_scene_vtp(glyphs, glyph_scale, trajectories, sources);
  return {trajectories, sources};
}

}  // namespace hsb
