#include "renderer/render/render_image.h"

#include "renderer/surface/embree_ray.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <limits>

namespace hsb {
namespace {

struct ThreadState {
  FieldRay tracer;
  TraceStats stats;
  std::uint64_t primary_rays = 0;
  std::uint64_t shadow_rays = 0;
};

// A stateless integer hash (the finaliser of MurmurHash3) turned into a
// number in [0, 1): jitter that depends only on the pixel and sample.
double hash_unit(std::uint64_t key) {
  key ^= key >> 33;
  key *= 0xff51afd7ed558ccdULL;
  key ^= key >> 33;
  key *= 0xc4ceb9fe1a85ec53ULL;
  key ^= key >> 33;
  return double(key >> 11) * (1.0 / 9007199254740992.0);
}

struct Sample {
  Rgb color;
  bool covered;
  double depth;
};

Sample trace_sample(const RayScene& scene, const ShadingSpec& shading, const Vec3& origin,
                    const Vec3& direction, const Vec3& to_light, double shadow_offset,
                    ThreadState& state) {
  FieldRayContext context(state.tracer, state.stats);
  RTCRayHit rh = make_embree_ray(origin, direction, 0.0f, INFINITY);
  rtcIntersect1(scene.get(), &context.embree, &rh);
  ++state.primary_rays;

  const unsigned id = rh.hit.geomID;
  if (id == RTC_INVALID_GEOMETRY_ID) return {shading.background, false, INFINITY};
  if (id == scene.box_id()) return {shading.box_color, true, double(rh.ray.tfar)};

  // The field's hit: the tracer kept t in double and the shading inputs.
  const Vec3 x = origin + context.t * direction;
  const Vec3& n = context.surface.normal;
  double visibility = 1.0;
  if (shading.shadows) {
    const Vec3 start = x + shadow_offset * (n.dot(direction) < 0.0 ? n : Vec3(-n));
    RTCRayHit shadow = make_embree_ray(start, to_light, 0.0f, INFINITY);
    FieldRayContext shadow_context(state.tracer, state.stats);
    rtcOccluded1(scene.get(), &shadow_context.embree, &shadow.ray);
    ++state.shadow_rays;
    if (shadow.ray.tfar < 0.0f) visibility = 0.0;
  }
  return {shade_surface(shading, context.surface.color, n, -direction, to_light, visibility), true,
          context.t};
}

// The shell's layers between the camera and `behind` (at distance t_behind),
// composited front to back. Opacity rises from shell_opacity facing the
// viewer to shell_edge_opacity at grazing angles, so the body's outline
// shows as an edge while glyphs inside stay visible.
Rgb composite_shell(RTCScene shell, const ShadingSpec& shading, const Vec3& origin,
                    const Vec3& direction, const Vec3& to_light, const Rgb& behind,
                    double t_behind) {
  constexpr int max_layers = 8;
  Rgb sum{0, 0, 0};
  double transmittance = 1.0;
  float t_near = 0.0f;
  const float t_far = std::isinf(t_behind) ? INFINITY : float(t_behind);
  for (int layer = 0; layer < max_layers; ++layer) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh = make_embree_ray(origin, direction, t_near, t_far);
    rtcIntersect1(shell, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;
    const Vec3 n = Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z).normalized();
    const double facing = std::fabs(n.dot(direction));
    const double grazing = std::pow(1.0 - facing, 3.0);
    const double alpha = shading.shell_opacity + (shading.shell_edge_opacity - shading.shell_opacity) * grazing;
    const double lit = shading.ambient + shading.light_intensity * std::fabs(n.dot(to_light));
    for (int c = 0; c < 3; ++c)
      sum[c] += float(transmittance * alpha * lit * shading.shell_color[c] * shading.light_color[c]);
    transmittance *= 1.0 - alpha;
    t_near = std::nextafter(rh.ray.tfar, INFINITY);
  }
  for (int c = 0; c < 3; ++c) sum[c] += float(transmittance) * behind[c];
  return sum;
}

}  // namespace

RenderOutput render_image(const RayScene& scene, const Box3& domain, const CameraSpec& camera_spec,
                          const ShadingSpec& shading, const RenderSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  const Camera camera(camera_spec, settings.width, settings.height);
  const Vec3 to_light = shading.light_from.normalized();
  const double shadow_offset = settings.shadow_offset * domain.diagonal();
  const int n = std::max(1, settings.samples);
  const double inv_samples = 1.0 / double(n * n);

  RenderOutput out{Film(settings.width, settings.height), {}, 0, 0, 0.0};
  tbb::enumerable_thread_specific<ThreadState> states;

  tbb::parallel_for(tbb::blocked_range<int>(0, settings.height), [&](const tbb::blocked_range<int>& rows) {
    ThreadState& state = states.local();
    for (int y = rows.begin(); y < rows.end(); ++y) {
      for (int x = 0; x < settings.width; ++x) {
        double rgb[3] = {0, 0, 0};
        double coverage = 0.0;
        double depth = INFINITY;
        const std::uint64_t pixel = std::uint64_t(y) * std::uint64_t(settings.width) + std::uint64_t(x);
        for (int sy = 0; sy < n; ++sy) {
          for (int sx = 0; sx < n; ++sx) {
            const std::uint64_t key = (pixel * std::uint64_t(n * n) + std::uint64_t(sy * n + sx)) * 2;
            const double jx = n == 1 ? 0.5 : (sx + hash_unit(key)) / n;
            const double jy = n == 1 ? 0.5 : (sy + hash_unit(key + 1)) / n;
            const Vec3 direction = camera.direction(x + jx, y + jy);
            Sample s = trace_sample(scene, shading, camera.origin(), direction, to_light, shadow_offset, state);
            if (scene.shell())
              s.color = composite_shell(scene.shell(), shading, camera.origin(), direction, to_light, s.color, s.depth);
            for (int c = 0; c < 3; ++c) rgb[c] += s.color[c];
            coverage += s.covered ? 1.0 : 0.0;
            depth = std::min(depth, s.depth);
          }
        }
        float* p = out.film.pixel(x, y);
        for (int c = 0; c < 3; ++c) p[c] = float(rgb[c] * inv_samples);
        p[3] = float(coverage * inv_samples);
        out.film.depth[pixel] = float(depth);
      }
    }
  });

  for (const ThreadState& state : states) {
    out.stats += state.stats;
    out.primary_rays += state.primary_rays;
    out.shadow_rays += state.shadow_rays;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace hsb
