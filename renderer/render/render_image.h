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
  // Shadow rays start this far off the surface along its normal, in units
  // of the domain's diagonal.
  double shadow_offset = 1e-5;
};

struct RenderOutput {
  Film film;
  TraceStats stats;
  std::uint64_t primary_rays = 0;
  std::uint64_t shadow_rays = 0;
  double seconds = 0.0;
};

RenderOutput render_image(const RayScene& scene, const Box3& domain, const CameraSpec& camera,
                          const ShadingSpec& shading, const RenderSettings& settings);

}  // namespace hsb
