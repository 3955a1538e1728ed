// The film: the same bytes whatever the thread count and however often a
// scene is rendered; alpha that composites; the pixel filter's weights.

#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include <atomic>
#include <thread>

#include "renderer/library/prepared_scene.h"
#include "renderer/render/pixel_filter.h"
#include "renderer/render/ray_scene.h"

namespace hsb {
namespace {

RenderOutput render(const std::string& scene, const std::vector<std::string>& overrides) {
  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> p = prepare_scene(load_scene_text(scene, "film.toml", "", overrides), color);
  static const EmbreeDevice device;
  const RayScene rays(device, p->field, p->trace, p->context);
  return render_image(rays, p->camera, p->shading, p->render);
}

// A blended pile with shadows, occlusion, a ground plane and the box: every
// kind of ray the renderer sends.
const std::string scene = "[[seeds.grid]]\ncorner = [-0.4, -0.4, 0.6]\nedge_u = [0.8, 0, 0]\nedge_v = [0, 0.8, 0]\n"
                          "n = 3\nm = 3\n[trajectories]\nfamily = \"minor\"\n[render]\nwidth = 61\nheight = 47\n"
                          "samples = 2\nground = true\n";

TEST(RenderImage, SameBytesForAnyThreadCountAndEveryRun) {
  RenderOutput two = render(scene, {});
  RenderOutput again = render(scene, {});
  const RenderOutput one = [] {
    const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    return render(scene, {});
  }();
  EXPECT_GT(two.shadow_rays, 0u);
  for (Plane p : {Plane::color, Plane::alpha}) {
    EXPECT_EQ(two.film.data(p), one.film.data(p)) << plane_info(p).name << ": 1 thread against 2";
    EXPECT_EQ(two.film.data(p), again.film.data(p)) << plane_info(p).name << ": a second run";
  }
}

// fig06's cap: hundreds of sources overlapping, where occlusion rays are
// traced against lists of the sources around them, each thread deciding
// from what it traced before (ambient_rays.h). The picture must not
// depend on those decisions.
TEST(RenderImage, SameBytesForAnyThreadCountOverADenseCrowd) {
  const std::string fig06 = std::string(HSB_SOURCE_DIR) + "/scenes/fig06_point_load_sqrt.toml";
  const std::vector<std::string> small = {"render.width=96", "render.height=96", "render.samples=2"};
  const auto render_fig06 = [&] {
    const ColorManagement color("", "");
    const std::unique_ptr<PreparedScene> p = prepare_scene(load_scene(fig06, small), color);
    static const EmbreeDevice device;
    const RayScene rays(device, p->field, p->trace, p->context);
    return render_image(rays, p->camera, p->shading, p->render);
  };
  const RenderOutput two = render_fig06();
  const RenderOutput one = [&] {
    const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    return render_fig06();
  }();
  // Most occlusion rays went against a list rather than through the BVH.
  EXPECT_LT(two.shadow_stats.span_queries, two.shadow_stats.field_rays);
  for (Plane p : {Plane::color, Plane::alpha})
    EXPECT_EQ(two.film.data(p), one.film.data(p)) << plane_info(p).name << ": 1 thread against 2";
}

// A render cancelled part-way (here after its first band of rows, as a
// viewer's next change or a Ctrl-C would) traces no further tile, throws
// RenderCancelled and leaves the scene usable: the same RayScene then
// renders the bytes a fresh render gives, and a render from another
// thread's cancel stops as well.
TEST(RenderImage, CancelledRenderStopsAndTheSceneStaysUsable) {
  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> p = prepare_scene(
      load_scene_text(scene, "film.toml", "", {"render.width=200", "render.height=160", "render.samples=3"}), color);
  static const EmbreeDevice device;
  const RayScene rays(device, p->field, p->trace, p->context);
  std::atomic<bool> cancel{false};
  int bands = 0;
  RenderSettings settings = p->render;
  settings.cancel = &cancel;
  settings.progress = [&](double) {
    ++bands;
    cancel = true;
  };
  EXPECT_THROW(render_image(rays, p->camera, p->shading, settings), RenderCancelled);
  EXPECT_EQ(bands, 1) << "bands made after the cancel";

  cancel = false;
  settings.progress = nullptr;
  const RenderOutput after = render_image(rays, p->camera, p->shading, settings);
  const RenderOutput fresh = render(scene, {"render.width=200", "render.height=160", "render.samples=3"});
  EXPECT_EQ(after.film.data(Plane::color), fresh.film.data(Plane::color));

  // From another thread, at once: nothing is left to trace.
  cancel = true;
  std::thread other([&] { EXPECT_THROW(render_image(rays, p->camera, p->shading, settings), RenderCancelled); });
  other.join();
}

TEST(RenderImage, TransparentBackgroundIsAlphaZeroOffTheGlyphsAndOneOnThem) {
  const RenderOutput out = render(scene, {"render.background=transparent", "render.ground=false",
                                          "render.box=false", "render.samples=1", "glyphs.mapping=normalized",
                                          "glyphs.scale=0.6", "render.width=160", "render.height=120"});
  const std::vector<float>& alpha = out.film.data(Plane::alpha);
  int clear = 0, solid = 0;
  for (std::size_t i = 0; i < alpha.size(); ++i) {
    clear += alpha[i] == 0.0f;
    solid += alpha[i] > 0.99f;
  }
  EXPECT_GT(clear, int(alpha.size()) / 4);  // the corners of the picture
  EXPECT_GT(solid, 10);                     // the glyphs
  // Off the glyphs the premultiplied colour is zero too.
  const std::vector<float>& color = out.film.data(Plane::color);
  for (std::size_t i = 0; i < alpha.size(); ++i) {
    if (alpha[i] == 0.0f) {
      EXPECT_EQ(color[3 * i] + color[3 * i + 1] + color[3 * i + 2], 0.0f);
    }
  }
}

TEST(RenderImage, GradientBackgroundRunsFromTopToBottom) {
  const RenderOutput out = render(scene, {"render.background=[1, 1, 1]", "render.background_bottom=[0, 0, 0]",
                                          "render.ground=false", "render.box=false", "render.samples=1",
                                          "glyphs.scale=1e-6", "glyphs.floor=1e-7"});
  const Film& film = out.film;
  const float top = film.data(Plane::color)[3 * std::size_t(film.width() / 2)];
  const float bottom = film.data(Plane::color)[3 * (std::size_t(film.height() - 1) * std::size_t(film.width()))];
  EXPECT_GT(top, 0.9f);
  EXPECT_LT(bottom, 0.05f);
}

TEST(PixelFilter, BlackmanHarrisIsOneAtTheCentreAndZeroAtTheRadius) {
  const int c = kFilterReach;  // the tap of the sample's own pixel
  const FilterTaps centred = filter_taps(0.5f, 0.5f);
  EXPECT_NEAR(centred.x[c], 1.0, 1e-5);
  EXPECT_NEAR(centred.y[c], 1.0, 1e-5);
  EXPECT_NEAR(centred.x[c - 1], centred.x[c + 1], 1e-12);  // symmetric
  EXPECT_GT(centred.x[c + 1], 0.0);
  // At a pixel's edge the centres one pixel beyond it are 1.5 pixels away.
  const FilterTaps at_edge = filter_taps(0.0f, 0.999f);
  EXPECT_EQ(at_edge.x[c - 1], 0.0);
  EXPECT_GT(at_edge.x[c + 1], 0.1);
  EXPECT_GT(at_edge.y[c + 1], 0.0);
  EXPECT_LT(at_edge.y[c + 1], 1e-4);
  // Mirrored positions weigh mirrored pixels alike.
  const FilterTaps left = filter_taps(0.25f, 0.5f), right = filter_taps(0.75f, 0.5f);
  for (int d = -kFilterReach; d <= kFilterReach; ++d) EXPECT_NEAR(left.x[c + d], right.x[c - d], 1e-12) << d;
}

}  // namespace
}  // namespace hsb
