#include "renderer/render/render_image.h"

#include "renderer/surface/embree_ray.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace hsb {
namespace {

struct ThreadState {
  FieldRayLanes tracers;
  TraceStats stats;
  std::uint64_t primary_rays = 0;
  std::uint64_t shadow_rays = 0;
  double primary_seconds = 0.0, shadow_seconds = 0.0;
};

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Camera rays are traced a tile of pixels at a time, one packet per
// sub-pixel sample: neighbouring rays meet the same sources.
constexpr int kTile = 4;
static_assert(kTile * kTile == kMaxPacket, "a tile fills one ray packet");

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

// Traces `count` (at most kMaxPacket) camera rays as one packet, and their
// shadow rays as another.
void trace_packet(const RayScene& scene, const ShadingSpec& shading, const CameraRay* rays, int count,
                  const Vec3& to_light, double shadow_offset, ThreadState& state, Sample* samples) {
  FieldRayContext context(state.tracers, state.stats);
  context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(64) int valid[kMaxPacket];
  alignas(64) RTCRayHit16 primary{};
  auto* primary_n = reinterpret_cast<RTCRayHitN*>(&primary);
  for (int i = 0; i < kMaxPacket; ++i) {
    valid[i] = i < count ? -1 : 0;
    if (i < count) set_embree_ray(primary_n, kMaxPacket, unsigned(i), rays[i].origin, rays[i].direction, 0.0f, INFINITY);
  }
  const auto primary_start = Clock::now();
  rtcIntersect16(valid, scene.get(), &context.embree, &primary);
  state.primary_seconds += seconds_since(primary_start);
  state.primary_rays += unsigned(count);

  // The field's hits: the tracer kept t in double and the shading inputs.
  alignas(64) int shadow_valid[kMaxPacket] = {};
  alignas(64) RTCRayHit16 shadow{};
  auto* shadow_n = reinterpret_cast<RTCRayHitN*>(&shadow);
  int shadow_count = 0;
  bool on_field[kMaxPacket] = {};
  for (int i = 0; i < count; ++i) {
    const unsigned id = primary.hit.geomID[i];
    if (id == RTC_INVALID_GEOMETRY_ID) {
      samples[i] = {shading.background, false, INFINITY};
      continue;
    }
    if (id == scene.box_id()) {
      samples[i] = {shading.box_color, true, double(primary.ray.tfar[i])};
      continue;
    }
    on_field[i] = true;
    const Vec3& n = context.surface[std::size_t(i)].normal;
    const Vec3 facing = n.dot(rays[i].direction) < 0.0 ? n : Vec3(-n);  // the side the camera sees
    // A side facing away from the light is unlit whatever lies between.
    if (shading.shadows && facing.dot(to_light) > 0.0) {
      const Vec3 x = rays[i].origin + context.t[std::size_t(i)] * rays[i].direction;
      const Vec3 start = x + shadow_offset * facing;
      set_embree_ray(shadow_n, kMaxPacket, unsigned(i), start, to_light, 0.0f, INFINITY,
                     RayScene::kShadowRayMask);
      shadow_valid[i] = -1;
      ++shadow_count;
    }
  }
  if (shadow_count > 0) {
    FieldRayContext shadow_context(state.tracers, state.stats);
    shadow_context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // parallel rays from nearby points
    const auto shadow_start = Clock::now();
    rtcOccluded16(shadow_valid, scene.get(), &shadow_context.embree, &shadow.ray);
    state.shadow_seconds += seconds_since(shadow_start);
    state.shadow_rays += unsigned(shadow_count);
  }
  for (int i = 0; i < count; ++i) {
    if (!on_field[i]) continue;
    const SurfaceSample& surface = context.surface[std::size_t(i)];
    const double visibility = shadow_valid[i] && shadow.ray.tfar[i] < 0.0f ? 0.0 : 1.0;
    samples[i] = {shade_surface(shading, surface.color, surface.normal, -rays[i].direction, to_light, visibility),
                  true, context.t[std::size_t(i)]};
  }
}

// The shell's layers between the camera and `behind` (at distance t_behind),
// composited front to back. Opacity rises from shell_opacity facing the
// viewer to shell_edge_opacity at grazing angles, so the body's outline
// shows as an edge while glyphs inside stay visible.
Rgb composite_shell(RTCScene shell, const ShadingSpec& shading, const CameraRay& ray, const Vec3& to_light,
                    const Rgb& behind, double t_behind) {
  const Vec3 &origin = ray.origin, &direction = ray.direction;
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

RenderOutput render_image(const RayScene& scene, const CameraSpec& camera_spec, const ShadingSpec& shading,
                          const RenderSettings& settings) {
  const auto start = Clock::now();
  const Camera camera(camera_spec, settings.width, settings.height);
  const Vec3 to_light = shading.light_from.normalized();
  const double shadow_offset = settings.shadow_offset;
  const int n = std::max(1, settings.samples);
  const double inv_samples = 1.0 / double(n * n);

  RenderOutput out{Film(settings.width, settings.height), {}, 0, 0, 0.0};
  tbb::enumerable_thread_specific<ThreadState> states;

  const int tiles_x = (settings.width + kTile - 1) / kTile;
  const int tiles_y = (settings.height + kTile - 1) / kTile;
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles_y), [&](const tbb::blocked_range<int>& tile_rows) {
    ThreadState& state = states.local();
    for (int ty = tile_rows.begin(); ty < tile_rows.end(); ++ty) {
      for (int tx = 0; tx < tiles_x; ++tx) {
        // The tile's pixels (fewer at the image's right and bottom edges).
        int px[kMaxPacket], py[kMaxPacket];
        std::uint64_t pixel[kMaxPacket];  // index into the film
        int count = 0;
        for (int dy = 0; dy < kTile; ++dy)
          for (int dx = 0; dx < kTile; ++dx) {
            const int x = tx * kTile + dx, y = ty * kTile + dy;
            if (x >= settings.width || y >= settings.height) continue;
            px[count] = x;
            py[count] = y;
            pixel[count++] = std::uint64_t(y) * std::uint64_t(settings.width) + std::uint64_t(x);
          }
        double rgb[kMaxPacket][3] = {};
        double coverage[kMaxPacket] = {};
        double depth[kMaxPacket];
        std::fill(depth, depth + kMaxPacket, INFINITY);
        for (int sy = 0; sy < n; ++sy) {
          for (int sx = 0; sx < n; ++sx) {
            CameraRay rays[kMaxPacket];
            for (int i = 0; i < count; ++i) {
              const std::uint64_t key = (pixel[i] * std::uint64_t(n * n) + std::uint64_t(sy * n + sx)) * 2;
              const double jx = n == 1 ? 0.5 : (sx + hash_unit(key)) / n;
              const double jy = n == 1 ? 0.5 : (sy + hash_unit(key + 1)) / n;
              rays[i] = camera.ray(px[i] + jx, py[i] + jy);
            }
            Sample samples[kMaxPacket];
            trace_packet(scene, shading, rays, count, to_light, shadow_offset, state, samples);
            for (int i = 0; i < count; ++i) {
              Sample& s = samples[i];
              if (scene.shell())
                s.color = composite_shell(scene.shell(), shading, rays[i], to_light, s.color, s.depth);
              for (int c = 0; c < 3; ++c) rgb[i][c] += s.color[c];
              coverage[i] += s.covered ? 1.0 : 0.0;
              depth[i] = std::min(depth[i], s.depth);
            }
          }
        }
        for (int i = 0; i < count; ++i) {
          float* p = out.film.pixel(px[i], py[i]);
          for (int c = 0; c < 3; ++c) p[c] = float(rgb[i][c] * inv_samples);
          p[3] = float(coverage[i] * inv_samples);
          out.film.depth[pixel[i]] = float(depth[i]);
        }
      }
    }
  });

  for (const ThreadState& state : states) {
    out.stats += state.stats;
    out.primary_rays += state.primary_rays;
    out.shadow_rays += state.shadow_rays;
    out.primary_seconds += state.primary_seconds;
    out.shadow_seconds += state.shadow_seconds;
  }
  out.threads = std::max<int>(1, int(states.size()));
  out.seconds = seconds_since(start);
  return out;
}

}  // namespace hsb
