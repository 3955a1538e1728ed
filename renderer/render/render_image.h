#pragma once
// Camera rays → first hits → lights and occlusion → samples → a film.
//
// The picture is made in bands of rows. A band's camera samples are traced
// (in 4×4-pixel packets, in parallel), then each pixel gathers the samples
// of the pixels around it through the pixel filter (pixel_filter.h) by the
// rules of its film planes (film.h). Every random number is a hash of what
// it is for, and every sum is taken in the same order, so a render gives the
// same bytes whatever the thread count; memory beyond the film is a few
// bands of samples, whatever the picture's size, and the film itself is a
// band where the picture is handed on as it is made (rows_done).

#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <vector>

#include "renderer/render/camera.h"
#include "renderer/render/film.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/shading.h"

namespace hsb {

struct RenderSettings {
  int width = 800;
  int height = 800;
  // Anti-aliasing: samples×samples stratified, jittered camera samples a
  // pixel, reconstructed with the pixel filter.
  int samples = 2;
  // Shadow and occlusion rays start this far off the surface along its normal.
  double shadow_offset = 1e-5;
  // Film planes besides colour and alpha (an EXR's layers).
  std::vector<Plane> planes;
  // Called after each band with the fraction of the picture made; empty:
  // nobody is watching.
  std::function<void(double)> progress;
  // When set, the picture goes here a band at a time as it is made, rows
  // [first, last) of the film in order, and the film holds only the band
  // being made (Film's window): RenderOutput::film is left with the last.
  std::function<void(const Film& film, int first, int last)> rows_done;
  // Polled before each 4×4 tile: once it holds true, no more rays are
  // traced and render_image() throws RenderCancelled, a tile's time later
  // (a viewer's next change, a user's Ctrl-C). Null: the render runs to
  // its end.
  const std::atomic<bool>* cancel = nullptr;
};

// What render_image() throws when RenderSettings::cancel was set. The
// scene, the device and whatever the caller holds stay usable.
struct RenderCancelled : std::exception {
  const char* what() const noexcept override { return "the render was cancelled"; }
};

struct RenderOutput {
  Film film;
  TraceStats stats;         // camera rays (and the shell's layers)
  TraceStats shadow_stats;  // key-light shadow and ambient occlusion rays
  std::uint64_t primary_rays = 0;
  std::uint64_t shadow_rays = 0;  // key-light shadows and ambient occlusion
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
