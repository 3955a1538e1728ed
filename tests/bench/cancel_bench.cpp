// How soon a render stops once cancelled (RenderSettings::cancel): the
// time from setting the flag to render_image() throwing, for a scene at
// its own full-quality settings, cancelled at several points of its
// render. A viewer cancels the pass in flight on every change, so this
// is the delay a change waits before its new pass starts.
//
//   cancel_bench [scene.toml] [runs]   (default scenes/fig09_point_load_hyperstreamsurface.toml, 5)
//
// Prints, per cancel point: the median and the largest delay in ms, and
// the full render's time for comparison. Measures; never fails on a
// number.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "renderer/library/prepared_scene.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/render_image.h"

namespace {

using namespace hsb;
using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path =
      argc > 1 ? argv[1] : std::string(HSB_SOURCE_DIR) + "/scenes/fig09_point_load_hyperstreamsurface.toml";
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> p = prepare_scene(load_scene(path, {}), color);
  const EmbreeDevice device;
  const RayScene scene(device, p->field, p->trace, p->context);

  const auto start = Clock::now();
  render_image(scene, p->camera, p->shading, p->render);
  const double full = ms_between(start, Clock::now());
  std::printf("%s: %dx%d, %d samples, %zu sources: full render %.0f ms\n", path.c_str(), p->render.width,
              p->render.height, p->render.samples, p->field.sources.size(), full);
  std::printf("%-22s %12s %12s\n", "cancelled after", "median ms", "largest ms");
  for (const double fraction : {0.05, 0.25, 0.5, 0.75}) {
    std::vector<double> delays;
    for (int run = 0; run < runs; ++run) {
      std::atomic<bool> cancel{false};
      RenderSettings settings = p->render;
      settings.cancel = &cancel;
      Clock::time_point set, stopped;
      std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(fraction * full));
        set = Clock::now();
        cancel = true;
      });
      try {
        render_image(scene, p->camera, p->shading, settings);
      } catch (const RenderCancelled&) {
      }
      stopped = Clock::now();
      canceller.join();
      delays.push_back(std::max(0.0, ms_between(set, stopped)));
    }
    std::sort(delays.begin(), delays.end());
    std::printf("%5.0f %% of the render   %12.2f %12.2f\n", 100.0 * fraction, delays[delays.size() / 2],
                delays.back());
  }
  return 0;
}
