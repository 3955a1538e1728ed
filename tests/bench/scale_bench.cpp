// How the renderer scales with the number of sources.
//
//   scale_bench [max_sources]      (default 1000000)
//
// For N = 10³ … max_sources: N discrete glyphs (random orientation,
// anisotropic, touching their neighbours) on a cubic lattice filling the
// same cube, so the screen coverage is the same for every N; one key light
// with shadows; a 1000×1000 image, one sample per pixel. Prints, per N: the
// time to build the field and its Embree BVH; peak memory per source while
// building (sources and BVH) and over the whole run (adding the film, 20 MB
// at this size, and the renderer's per-thread state); primary and shadow
// Mrays/s; support intervals and field evaluations per ray; and the whole
// render's time. Measures; never fails on a number.

#include <malloc.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "base/process_memory.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/render_image.h"
#include "renderer/surface/instruction_set.h"

namespace {

using namespace hsb;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

BlobField lattice_of_glyphs(long n_target) {
  const int side = int(std::lround(std::cbrt(double(n_target))));
  const double spacing = 2.0 / side;
  std::mt19937 rng(42);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  BlobField field;
  field.sources.reserve(std::size_t(side) * side * side);
  for (int k = 0; k < side; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        const Vec3 centre = Vec3(-1, -1, -1) + spacing * Vec3(i + 0.5, j + 0.5, k + 0.5);
        const Mat3 axes = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
        // Visible semi-axes R r/2 up to 0.55 spacing: neighbours touch and blend.
        const Vec3 radii = spacing * Vec3(1.1, 0.4 + 0.5 * u(rng), 0.25 + 0.3 * u(rng));
        const std::array<float, 3> color{float(0.2 + 0.6 * u(rng)), 0.5f, float(0.8 - 0.6 * u(rng))};
        field.sources.push_back(make_blob_source(centre, axes, radii, 1.0, color));
      }
  return field;
}

}  // namespace

int main(int argc, char** argv) {
  const long max_sources = argc > 1 ? std::atol(argv[1]) : 1000000;
  const EmbreeDevice device;
  const Box3 domain{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
  CameraSpec camera;
  camera.position = Vec3(2.2, -3.4, 2.0);
  camera.look_at = Vec3::Zero();
  camera.fov_degrees = 34;
  ShadingSpec shading;
  RenderSettings render;
  render.width = render.height = 1000;
  render.samples = 1;
  TraceSettings trace;
  trace.min_step = 1e-6 * domain.diagonal();
  render.shadow_offset = 1e-5 * domain.diagonal();

  std::printf("%9s %8s %10s %10s %10s %10s %9s %9s %9s\n", "sources", "build_s", "bytes/src", "bytes/src",
              "primary", "shadow", "spans/ray", "evals/ray", "render_s");
  std::printf("%9s %8s %10s %10s %10s %10s %9s %9s %9s\n", "", "", "(build)", "(render)", "Mrays/s", "Mrays/s",
              "", "", "(1 MP)");
  for (long n = 1000; n <= max_sources; n *= 10) {
    // Hand the previous size's freed memory back to the system, or this
    // size would reuse it without raising the resident set.
    malloc_trim(0);
    reset_peak_resident();
    const double rss_before = resident_bytes();
    const auto t0 = Clock::now();
    const BlobField field = lattice_of_glyphs(n);
    const RayScene scene(device, field, trace);
    const double build = seconds_since(t0);
    const double build_bytes = (peak_resident_bytes() - rss_before) / double(field.sources.size());

    const RenderOutput full = render_image(scene, camera, shading, render);
    const double total_bytes = (peak_resident_bytes() - rss_before) / double(field.sources.size());
    const double rays = double(std::max<std::uint64_t>(1, full.stats.field_rays));
    std::printf("%9zu %8.2f %10.0f %10.0f %10.2f %10.2f %9.1f %9.1f %9.2f\n", field.sources.size(), build,
                build_bytes, total_bytes,
                full.primary_mrays_per_second(), full.shadow_mrays_per_second(), double(full.stats.spans) / rays,
                double(full.stats.field_evaluations) / rays, full.seconds);
    std::fflush(stdout);
  }
  std::printf("(1000x1000, 1 sample per pixel, one light with shadows; Mrays/s from the time spent in\n"
              " camera-ray and shadow-ray queries; instruction set %s, HSB_ISA forces another)\n",
              isa_name(device.isa()));
  return 0;
}
