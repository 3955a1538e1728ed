#pragma once
// Camera rays → first hits → shading → a scene-linear film.

#include <cstdint>

#include "renderer/render/camera.h"
#include "renderer/render/film.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/shading.h"

namespace hsb {

struct RenderSettings {
  int width = 800;
  int height = 800;
  // Anti-aliasing: a samples×samples stratified, jittered grid per pixel,
  // box-filtered. The jitter is a hash of pixel and sample, so renders are
  // reproducible whatever the thread count.
  int samples = 2;
  // Shadow rays start this far off the surface along its normal.
  double shadow_offset = 1e-5;
};

struct RenderOutput {
  Film film;
  TraceStats stats;
  std::uint64_t primary_rays = 0;
  std::uint64_t shadow_rays = 0;
  double seconds = 0.0;
  // Time inside camera-ray and shadow-ray queries, summed over the threads
  // that rendered, and their number: the rates are what all threads
  // together achieve on that kind of ray.
  double primary_seconds = 0.0, shadow_seconds = 0.0;
  int threads = 1;

  double primary_mrays_per_second() const { return rate(primary_rays, primary_seconds); }
  double shadow_mrays_per_second() const { return rate(shadow_rays, shadow_seconds); }

 private:
  double rate(std::uint64_t rays, double thread_seconds) const {
    return thread_seconds > 0.0 ? double(rays) * threads / thread_seconds * 1e-6 : 0.0;
  }
};

RenderOutput render_image(const RayScene& scene, const CameraSpec& camera, const ShadingSpec& shading,
                          const RenderSettings& settings);

}  // namespace hsb
