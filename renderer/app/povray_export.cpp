#include "renderer/app/povray_export.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "base/partial_file.h"

namespace hsb {
namespace {

std::string vec(const Vec3& v) {
  char text[128];
  std::snprintf(text, sizeof text, "<%.9g, %.9g, %.9g>", v.x(), v.y(), v.z());
  return text;
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x);
  return text;
}

std::string rgb(const Rgb& c) { return vec(Vec3(c[0], c[1], c[2])); }

}  // namespace

void write_povray_scene(const BlobField& field, const CameraSpec& camera, const ShadingSpec& shading,
                        const RenderSettings& render, const std::string& pov_path,
                        const std::string& ini_path, const std::string& image_path) {
  if (field.kernel != KernelKind::quartic || field.blend != Blend::sum)
    throw std::invalid_argument(
        "POV-Ray's blob is the quartic kernel, summed: set surface.kernel = \"quartic\" and "
        "surface.blend = \"sum\" to export this scene");
  if (!shape_is_quadric(field.shape))
    throw std::invalid_argument(
        "POV-Ray's blob components are ellipsoids: set glyphs.shape = \"ellipsoid\" to export this scene "
        "(a superquadric has no blob equivalent)");
  // Both files are made in memory and written through PartialFile, like
  // every file hsb writes: a full disk or a signal leaves neither behind,
  // nor half of one.
  std::ostringstream pov;
  pov.precision(9);
  const double aspect = double(render.width) / double(render.height);
  const double half_v = std::tan(0.5 * camera.fov_degrees * M_PI / 180.0);
  const double fov_h = 2.0 * std::atan(half_v * aspect) * 180.0 / M_PI;  // POV's angle is horizontal
  // An orthographic view is as high as `up` is long.
  const bool orthographic = camera.projection == Projection::orthographic;
  const std::string projection = orthographic ? "orthographic" : "perspective";
  const std::string scale = orthographic ? "*" + number(camera.height) : "";
  const std::string angle = orthographic ? "" : "  angle " + number(fov_h) + "\n";
  const Box3 bounds = influence_bounds(field);
  const Vec3 light_position = bounds.centre() + 1e3 * bounds.diagonal() * shading.light_from.normalized();

  pov << "// Hyperstreamball scene for POV-Ray 3.7: " << field.sources.size() << " sources.\n"
      << "// Colours are scene-linear (assumed_gamma 1); the .ini asks for sRGB output.\n"
      << "#version 3.7;\n"
      << "global_settings { assumed_gamma 1.0 ambient_light rgb <1, 1, 1> }\n"
      << "background { rgb " << rgb(shading.background) << " }\n"
      // POV-Ray is left-handed; a negated `right` keeps this scene's
      // right-handed coordinates unmirrored.
      << "camera {\n  " << projection << "\n  location " << vec(camera.position) << "\n  sky " << vec(camera.up)
      << "\n  up y" << scale << "\n  right -x*" << aspect << scale << "\n" << angle << "  look_at "
      << vec(camera.look_at) << "\n}\n"
      << "light_source { " << vec(light_position) << " color rgb "
      << rgb({float(shading.light_intensity * shading.light_color[0]),
              float(shading.light_intensity * shading.light_color[1]),
              float(shading.light_intensity * shading.light_color[2])})
      << " parallel point_at " << vec(bounds.centre()) << (shading.shadows ? "" : " shadowless") << " }\n"
      << "#declare Finish = finish { ambient " << shading.ambient << " diffuse 1 specular " << shading.specular
      << " roughness " << 1.0 / shading.shininess << " }\n";
  // One blob per group of sources (BlobField::groups): each blends within
  // itself, and POV-Ray draws the blobs side by side, a union.
  for (const std::uint8_t group : field_groups(field)) {
    pov << "blob {\n  threshold " << field.isovalue << "\n";
    for (std::size_t i = 0; i < field.sources.size(); ++i) {
      if (!field.groups.empty() && field.groups[i] != group) continue;
      const BlobSource& s = field.sources[i];
      // The unit sphere mapped onto the influence ellipsoid: POV's matrix
      // rows are the images of x, y and z, here the ellipsoid's semi-axis
      // vectors (row k of W over its squared length).
      pov << "  sphere { <0, 0, 0>, 1, 1 matrix <";
      for (int k = 0; k < 3; ++k) {
        const Vec3 row(s.w[3 * k], s.w[3 * k + 1], s.w[3 * k + 2]);
        const Vec3 axis = row / row.squaredNorm();
        pov << axis.x() << ", " << axis.y() << ", " << axis.z() << ", ";
      }
      pov << s.centre[0] << ", " << s.centre[1] << ", " << s.centre[2] << "> texture { pigment { rgb "
          << rgb(s.color) << " } finish { Finish } } }\n";
    }
    pov << "}\n";
  }
  std::ostringstream ini;
  ini << "; Render with: povray " << ini_path << "  (add +WT2 for two threads)\n"
      << "Input_File_Name=" << pov_path << "\nOutput_File_Name=" << image_path
      << "\nWidth=" << render.width << "\nHeight=" << render.height
      << "\nAntialias=Off\nDisplay=Off\nOutput_File_Type=N\nFile_Gamma=sRGB\nDisplay_Gamma=sRGB\n"
      << "Verbose=Off\n";
  PartialFile pov_file(pov_path), ini_file(ini_path);
  const std::string pov_text = pov.str(), ini_text = ini.str();
  pov_file.write(pov_text.data(), pov_text.size());
  ini_file.write(ini_text.data(), ini_text.size());
  pov_file.commit();
  ini_file.commit();
}

}  // namespace hsb
