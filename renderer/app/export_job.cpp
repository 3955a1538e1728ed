#include "renderer/app/export_job.h"

#include <filesystem>

#include "field/glyphs/vtk_export.h"
#include "field/reading/data_formats.h"
#include "renderer/app/povray_export.h"
#include "renderer/library/prepared_scene.h"

namespace hsb {

namespace {

// A shaped glyph's parameters (glyph_shape.h), so its shape can be drawn
// or inspected elsewhere; none for the ellipsoid:
//  - "shape_exponents": Kindlmann's (α, β), the equatorial and axial
//    exponents (vtkSuperquadricSource's ThetaRoundness and PhiRoundness);
//  - "shape_axis": which axis (0, 1, 2, in the order of "radii" and
//    "eigenvalues") the superquadric is round about;
//  - "shape_points" (signed glyphs): 1 for each axis whose ends are
//    points, the axes that compress under data.sign, else 0.
std::vector<SourceArray> shape_arrays(const BlobField& field) {
  if (shape_is_quadric(field.shape)) return {};
  SourceArray exponents{"shape_exponents", 2, {}}, axis{"shape_axis", 1, {}}, points{"shape_points", 3, {}};
  for (const ShapeParams& s : field.shapes) {
    exponents.values.insert(exponents.values.end(), {double(s.alpha), double(s.beta)});
    axis.values.push_back(double(s.axis));
    for (int k = 0; k < 3; ++k) points.values.push_back(s.pointed & (1u << k) ? 1.0 : 0.0);
  }
  if (field.shape == GlyphShape::signed_superquadric) return {exponents, axis, points};
  return {exponents, axis};
}

}  // namespace

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
  write_glyph_scene_vtp(p->glyphs, 2.0 * glyph_extent(p->spec.surface), trajectories, sources, shape_arrays(p->field));
  return {trajectories, sources};
}

}  // namespace hsb
