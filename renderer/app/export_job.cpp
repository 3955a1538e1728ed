#include "renderer/app/export_job.h"

#include <filesystem>

#include "field/glyphs/vtk_export.h"
#include "field/reading/data_formats.h"
#include "renderer/app/povray_export.h"
#include "renderer/app/prepared_scene.h"

namespace hsb {

std::vector<std::string> run_export_job(const ExportJob& job) {
  SceneSpec spec = load_scene_or_data_file(job.scene_path, job.overrides);
  const std::filesystem::path dir(job.output_dir);
  std::filesystem::create_directories(dir);
  const std::string stem = file_stem(job.scene_path);
  const ColorManagement color = scene_color_management(spec);
  const std::unique_ptr<PreparedScene> p = prepare_scene(std::move(spec), color);

  if (job.format == ExportFormat::pov) {
    const std::string pov = (dir / (stem + ".pov")).string(), ini = (dir / (stem + ".ini")).string();
    write_povray_scene(p->field, p->camera, p->shading, p->render, pov, ini, (dir / (stem + ".povray.png")).string());
    return {pov, ini};
  }
  const std::string trajectories = (dir / (stem + "_trajectories.vtp")).string();
  const std::string sources = (dir / (stem + "_sources.vtp")).string();
  // Tensor Glyph's unit sphere has radius ½.
  write_glyph_scene_vtp(p->glyphs, 2.0 * glyph_extent(p->spec.surface), trajectories, sources);
  return {trajectories, sources};
}

}  // namespace hsb
