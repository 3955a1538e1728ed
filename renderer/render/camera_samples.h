#pragma once
// Camera samples: what one camera ray sees, lit and composited, ready for
// the film. Traced 16 at a time (a 4×4 tile of pixels, one sample each):
// the camera rays as one Embree packet, then their shadow and ambient
// occlusion rays in packets of 16.

#include <array>
#include <cstdint>

#include "renderer/render/ambient_rays.h"
#include "renderer/render/camera.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/shading.h"

namespace hsb {

struct CameraSample {
  float x = 0.0f, y = 0.0f;             // where in the picture, in pixels
  std::array<float, 3> color{0, 0, 0};  // scene-linear, premultiplied by alpha
  float alpha = 0.0f;
  float depth = INFINITY;               // camera distance of the first opaque hit
  std::array<float, 3> normal{0, 0, 0};  // the glyph surface's, when a glyph was hit
  float scalar = 0.0f;
  std::int32_t id = -1;                 // the glyph's source, −1 when none was hit
};

// Per-thread scratch and counters.
struct SampleTracer {
  FieldRayLanes tracers;
  // The tangent planes of each camera ray's glyph hit, for its occlusion
  // rays (support_planes.h).
  std::array<SupportPlanes, kMaxPacket> hit_planes;
  AmbientRays ambient;
  TraceStats stats;         // camera rays
  TraceStats shadow_stats;  // key-light shadow and ambient occlusion rays
  std::uint64_t primary_rays = 0, shadow_rays = 0;
  double primary_seconds = 0.0, shadow_seconds = 0.0;
};

// One camera ray of a packet: the ray, its pixel and sample number of the
// pixel's count (the keys of its random numbers: the light and occlusion
// rays of all a pixel's samples are stratified together), and how far down
// the picture it is.
struct CameraRayJob {
  CameraRay ray;
  std::uint64_t pixel = 0;
  std::uint32_t sample = 0, samples = 1;
  double picture_v = 0.0;  // 0 at the top, 1 at the bottom
};

// Traces `count` (at most kMaxPacket) camera rays and everything they need.
void trace_camera_samples(const RayScene& scene, const ShadingSpec& shading, double shadow_offset,
                          const CameraRayJob* jobs, int count, SampleTracer& tracer, CameraSample* out);

// The samples of `count` camera rays known to meet nothing (their part of
// the picture cannot see the scene's reach: camera_frustum.h), as
// trace_camera_samples makes them without tracing: the background, counted
// as camera rays. Not for a scene with a ground plane, whose shadow needs
// rays; the jobs' rays are not read.
void background_camera_samples(const ShadingSpec& shading, const CameraRayJob* jobs, int count, SampleTracer& tracer,
                               CameraSample* out);

}  // namespace hsb
