#include "renderer/app/export_job.h"

#include <filesystem>

#include "field/vtk_export.h"
#include "renderer/app/povray_export.h"
#include "renderer/app/prepared_scene.h"

namespace hsb {

std::vector<std::string> run_export_job(const ExportJob& job) {
  SceneSpec spec = load_scene(job.scene_path, job.overrides);
  const std::filesystem::path dir(job.output_dir);
  std::filesystem::create_directories(dir);
  const std::string stem = std::filesystem::path(job.scene_path).stem().string();

  if (job.format == ExportFormat::pov) {
    const ColorManagement color(spec.output.display, spec.output.view);
    const PreparedScene p = prepare_scene(std::move(spec), color);
    const std::string pov = (dir / (stem + ".pov")).string(), ini = (dir / (stem + ".ini")).string();
    write_povray_scene(p.field, p.camera, p.shading, p.spec.render, pov, ini,
                       (dir / (stem + ".povray.png")).string());
    return {pov, ini};
  }

  const GlyphScene glyphs = build_glyph_scene(spec.pipeline);
  const std::string trajectories = (dir / (stem + "_trajectories.vtp")).string();
  const std::string sources = (dir / (stem + "_sources.vtp")).string();
  // Tensor Glyph's unit sphere has radius ½.
  const double glyph_scale =
      2.0 * spec.surface.influence_radius * kernel_level_radius(spec.surface.kernel, spec.surface.isovalue);
  write_glyph_scene_vtp(glyphs, glyph_scale, trajectories, sources);
  return {trajectories, sources};
}

}  // namespace hsb
