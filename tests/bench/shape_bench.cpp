// What a glyph shape costs: the same sources rendered as ellipsoids and as
// superquadrics (glyph_shape.h).
//
//   shape_bench [SIZE]      (default 480: SIZE × SIZE pixels)
//
// For the paper's discrete point-load ellipsoids (fig05), its point-load
// hyperstreamlines (fig08) and cylinder ellipsoids (fig10): the scene with
// glyphs.shape = "ellipsoid" (the exact intersector, the default) and
// "superquadric" (sharpness 3, sphere traced), one sample per pixel, one
// light with shadows. And fig17, the cylinder's signed beads (glyphs end
// to end along each line, glyphs.beads = 0 pinned so that every shape has
// the same sources), as ellipsoids, superquadrics and its own signed
// glyphs. Prints, per scene and shape, the render's seconds (the best of
// three), primary and shadow Mrays/s, shape evaluations (field
// evaluations) and kernel evaluations per ray, and each shape's time as a
// multiple of the ellipsoid's. Measures; never
// fails on a number.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "renderer/app/prepared_scene.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/render_image.h"
#include "renderer/surface/instruction_set.h"

namespace {

using namespace hsb;

#ifndef HSB_SOURCE_DIR
#define HSB_SOURCE_DIR "."
#endif

double per_ray(std::uint64_t count, const TraceStats& stats) {
  return double(count) / double(std::max<std::uint64_t>(1, stats.field_rays));
}

// The best of three renders of one scene in one shape.
RenderOutput render_shape(const EmbreeDevice& device, const std::string& path, const std::string& shape,
                          const std::vector<std::string>& settings, int size, std::size_t& sources) {
  std::vector<std::string> overrides = {"render.width=" + std::to_string(size), "render.height=" + std::to_string(size),
                                        "render.samples=1", "glyphs.shape=\"" + shape + "\""};
  overrides.insert(overrides.end(), settings.begin(), settings.end());
  SceneSpec spec = load_scene(path, overrides);
  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> p = prepare_scene(std::move(spec), color);
  sources = p->field.sources.size();
  const RayScene scene(device, p->field, p->trace, p->context);
  RenderOutput best = render_image(scene, p->camera, p->shading, p->render);
  for (int i = 0; i < 2; ++i) {
    RenderOutput again = render_image(scene, p->camera, p->shading, p->render);
    if (again.seconds < best.seconds) best = std::move(again);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const int size = argc > 1 ? std::atoi(argv[1]) : 480;
  const std::string dir = std::string(HSB_SOURCE_DIR) + "/scenes/";
  const EmbreeDevice device;
  std::printf("%-38s %-13s %7s %8s %8s %8s %10s %10s %10s %7s\n", "scene", "shape", "sources", "render_s",
              "primary", "shadow", "evals/ray", "kernels", "kernels", "time");
  std::printf("%-38s %-13s %7s %8s %8s %8s %10s %10s %10s %7s\n", "", "", "", "", "Mrays/s", "Mrays/s", "(camera)",
              "/ray cam", "/ray shad", "ratio");
  struct Case {
    const char* name;
    std::vector<std::string> shapes, settings;
  };
  const std::vector<std::string> plain = {"ellipsoid", "superquadric"};
  const Case cases[] = {
      {"fig05_point_load_linear", plain, {}},
      {"fig08_point_load_hyperstreamlines", plain, {}},
      {"fig10_cylinder_ellipsoids", plain, {}},
      {"fig17_cylinder_signed_hyperstreamlines", {"ellipsoid", "superquadric", "signed"}, {"glyphs.beads=0"}}};
  for (const Case& c : cases) {
    const char* name = c.name;
    double ellipsoid_seconds = 0.0;
    for (const std::string& shape : c.shapes) {
      std::size_t sources = 0;
      const RenderOutput o = render_shape(device, dir + name + ".toml", shape, c.settings, size, sources);
      if (shape == "ellipsoid") ellipsoid_seconds = o.seconds;
      std::printf("%-38s %-13s %7zu %8.3f %8.2f %8.2f %10.2f %10.1f %10.1f %7.2f\n", name, shape.c_str(), sources,
                  o.seconds, o.primary_mrays_per_second(), o.shadow_mrays_per_second(),
                  per_ray(o.stats.field_evaluations, o.stats), per_ray(o.stats.kernel_evaluations, o.stats),
                  per_ray(o.shadow_stats.kernel_evaluations, o.shadow_stats), o.seconds / ellipsoid_seconds);
      std::fflush(stdout);
    }
  }
  std::printf("(%d×%d, 1 sample per pixel, one light with shadows, best of three renders; ratio: the render's\n"
              " time over the ellipsoid's; instruction set %s, HSB_ISA forces another)\n",
              size, size, isa_name(device.isa()));
  return 0;
}
