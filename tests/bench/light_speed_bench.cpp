// The speed of light of this design: how close the blended field comes to
// the least a ray tracer on Embree can do with the same sources.
//
//   light_speed_bench [SIZE] [SCENE.toml ...]
//       (default 800: SIZE × SIZE pixels; fig05, fig09 and fig14)
//
// The peer is a minimal Embree user geometry: one primitive per source, the
// hard ellipsoid an isolated source draws (g = u², u the kernel's level
// radius), bounded by its box and intersected analytically, nothing else.
// The same camera rays, one through each pixel's centre, go through it and
// through the renderer's field geometry (BlobGeometry) as a union
// (surface.blend = "max", whose surface is exactly those ellipsoids) and
// as the scene's blend; then each hit sends one shadow ray towards the
// key light. Both are traced the same way the renderer traces (16-ray
// groups in packets of the device's native width, coherent, every core),
// and only tracing is timed: what shading and the film cost is the same
// whichever geometry the rays meet. Prints Mrays/s for each, the field's
// rate as a fraction of the light's (the targets: a union at ≥ ½, a blend
// at ≥ ¼), and how many pixels the union and the ellipsoids agree on,
// surface against background. Measures; never fails on a number.

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "renderer/library/prepared_scene.h"
#include "renderer/render/camera.h"
#include "renderer/render/ray_scene.h"
#include "renderer/surface/embree_ray.h"
#include "renderer/surface/instruction_set.h"
#include "renderer/surface/ray_packets.h"

namespace {

using namespace hsb;
using Clock = std::chrono::steady_clock;

#ifndef HSB_SOURCE_DIR
#define HSB_SOURCE_DIR "."
#endif

// The sources as hard ellipsoids |W (x − c)|² ≤ 1, W scaled so that 1 is
// the isolated source's level set.
class HardEllipsoids {
 public:
  HardEllipsoids(const EmbreeDevice& device, const BlobField& field) {
    const double level = kernel_level_radius(field.kernel, field.isovalue);
    for (std::size_t i = 0; i < field.sources.size(); ++i) {
      const BlobSource& s = field.sources[i];
      Ellipsoid e;
      for (int k = 0; k < 9; ++k) e.w[k] = double(s.w[std::size_t(k)]) / level;
      for (int k = 0; k < 3; ++k) e.c[k] = s.centre[std::size_t(k)];
      // The influence box is that of g ≤ 1; the level set's is u times it.
      const Box3 influence = influence_bounds(field, i);
      const Vec3 centre(e.c[0], e.c[1], e.c[2]);
      e.box = {centre - level * (centre - influence.lo), centre + level * (influence.hi - centre)};
      ellipsoids_.push_back(e);
    }
    scene_ = rtcNewScene(device.get());
    RTCGeometry g = rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, unsigned(ellipsoids_.size()));
    rtcSetGeometryUserData(g, this);
    rtcSetGeometryBoundsFunction(g, bounds, nullptr);
    rtcSetGeometryIntersectFunction(g, intersect);
    rtcSetGeometryOccludedFunction(g, occluded);
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene_, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene_);
  }
  ~HardEllipsoids() { rtcReleaseScene(scene_); }
  HardEllipsoids(const HardEllipsoids&) = delete;
  HardEllipsoids& operator=(const HardEllipsoids&) = delete;

  RTCScene get() const { return scene_; }

 private:
  struct Ellipsoid {
    double w[9], c[3];
    Box3 box;
  };

  // The ray's entry into ellipsoid `e` within [tnear, tfar] (or its exit,
  // when it starts inside), and the outward normal there; false if none.
  static bool cross(const Ellipsoid& e, const Vec3& o, const Vec3& d, double tnear, double tfar, double& t,
                    Vec3& normal) {
    Vec3 q0, qd;
    for (int r = 0; r < 3; ++r) {
      q0[r] = e.w[3 * r] * (o.x() - e.c[0]) + e.w[3 * r + 1] * (o.y() - e.c[1]) + e.w[3 * r + 2] * (o.z() - e.c[2]);
      qd[r] = e.w[3 * r] * d.x() + e.w[3 * r + 1] * d.y() + e.w[3 * r + 2] * d.z();
    }
    const double a = qd.squaredNorm(), b = q0.dot(qd), c = q0.squaredNorm() - 1.0;
    const double disc = b * b - a * c;
    if (disc < 0.0 || a <= 0.0) return false;
    const double root = std::sqrt(disc);
    const double near = (-b - root) / a, far = (-b + root) / a;
    t = near >= tnear ? near : far;
    if (t < tnear || t > tfar) return false;
    const Vec3 q = q0 + t * qd;
    normal = Vec3(e.w[0] * q[0] + e.w[3] * q[1] + e.w[6] * q[2], e.w[1] * q[0] + e.w[4] * q[1] + e.w[7] * q[2],
                  e.w[2] * q[0] + e.w[5] * q[1] + e.w[8] * q[2]);
    return true;
  }

  static void bounds(const RTCBoundsFunctionArguments* args) {
    const auto* self = static_cast<const HardEllipsoids*>(args->geometryUserPtr);
    const Box3& b = self->ellipsoids_[args->primID].box;
    *args->bounds_o = {float(b.lo.x()), float(b.lo.y()), float(b.lo.z()), 0.0f,
                       float(b.hi.x()), float(b.hi.y()), float(b.hi.z()), 0.0f};
  }

  static void intersect(const RTCIntersectFunctionNArguments* args) {
    const auto* self = static_cast<const HardEllipsoids*>(args->geometryUserPtr);
    const Ellipsoid& e = self->ellipsoids_[args->primID];
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
      if (args->valid[i] != -1) continue;
      double t;
      Vec3 n;
      if (!cross(e, embree_ray_origin(rays, args->N, i), embree_ray_direction(rays, args->N, i),
                 RTCRayN_tnear(rays, args->N, i), RTCRayN_tfar(rays, args->N, i), t, n))
        continue;
      RTCRayN_tfar(rays, args->N, i) = float(t);
      RTCHitN_Ng_x(hits, args->N, i) = float(n.x());
      RTCHitN_Ng_y(hits, args->N, i) = float(n.y());
      RTCHitN_Ng_z(hits, args->N, i) = float(n.z());
      RTCHitN_primID(hits, args->N, i) = args->primID;
      RTCHitN_geomID(hits, args->N, i) = args->geomID;
    }
  }

  static void occluded(const RTCOccludedFunctionNArguments* args) {
    const auto* self = static_cast<const HardEllipsoids*>(args->geometryUserPtr);
    const Ellipsoid& e = self->ellipsoids_[args->primID];
    for (unsigned i = 0; i < args->N; ++i) {
      if (args->valid[i] != -1) continue;
      double t;
      Vec3 n;
      if (cross(e, embree_ray_origin(args->ray, args->N, i), embree_ray_direction(args->ray, args->N, i),
                RTCRayN_tnear(args->ray, args->N, i), RTCRayN_tfar(args->ray, args->N, i), t, n))
        RTCRayN_tfar(args->ray, args->N, i) = -INFINITY;
    }
  }

  std::vector<Ellipsoid> ellipsoids_;
  RTCScene scene_ = nullptr;
};

// One geometry's two passes: camera rays, then a shadow ray from each hit.
struct Pass {
  double primary_seconds = 0.0, shadow_seconds = 0.0;
  std::size_t primary_rays = 0, shadow_rays = 0;
  std::vector<float> depth;  // per pixel; infinite where the ray met nothing
  double primary_mrays() const { return 1e-6 * double(primary_rays) / primary_seconds; }
  double shadow_mrays() const { return 1e-6 * double(shadow_rays) / shadow_seconds; }
};

struct Scratch {
  FieldRayLanes tracers;
  TraceStats stats;
};

constexpr int kTile = 4;  // 4 × 4 pixels: one 16-ray group

// The pixels in tile order: each run of 16 is one 4 × 4 tile, clipped at
// the picture's edge, so a group of rays is as coherent as the renderer's.
std::vector<int> pixels_by_tile(int size) {
  std::vector<int> pixels;
  const int tiles = (size + kTile - 1) / kTile;
  for (int tile = 0; tile < tiles * tiles; ++tile)
    for (int dy = 0; dy < kTile; ++dy)
      for (int dx = 0; dx < kTile; ++dx) {
        const int x = (tile % tiles) * kTile + dx, y = (tile / tiles) * kTile + dy;
        if (x < size && y < size) pixels.push_back(y * size + x);
      }
  return pixels;
}

// Calls trace_group(context, first, count) for each group of up to 16 of
// `total` rays, on every core, and returns the wall time.
template <class TraceGroup>
double over_groups(std::size_t total, tbb::enumerable_thread_specific<Scratch>& scratch, TraceGroup&& trace_group) {
  const std::size_t groups = (total + kMaxPacket - 1) / kMaxPacket;
  const auto start = Clock::now();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups), [&](const tbb::blocked_range<std::size_t>& range) {
    Scratch& s = scratch.local();
    FieldRayContext context(s.tracers, s.stats);
    context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    for (std::size_t g = range.begin(); g != range.end(); ++g) {
      const std::size_t first = g * kMaxPacket;
      trace_group(context, first, int(std::min<std::size_t>(kMaxPacket, total - first)));
    }
  });
  return std::chrono::duration<double>(Clock::now() - start).count();
}

Pass trace_passes(RTCScene scene, int width, const Camera& camera, int size, const Vec3& light, double offset) {
  tbb::enumerable_thread_specific<Scratch> scratch;
  Pass pass;
  pass.depth.assign(std::size_t(size) * std::size_t(size), INFINITY);
  auto camera_ray = [&](int pixel) { return camera.ray(pixel % size + 0.5, pixel / size + 0.5); };
  const std::vector<int> pixels = pixels_by_tile(size);
  pass.primary_seconds = over_groups(pixels.size(), scratch, [&](FieldRayContext& context, std::size_t first, int count) {
    intersect_rays(
        scene, &context.embree, width, first_rays(count),
        [&](RTCRayHitN* packet, unsigned w, unsigned lane, int i) {
          const CameraRay r = camera_ray(pixels[first + std::size_t(i)]);
          set_embree_ray(packet, w, lane, unsigned(i), r.origin, r.direction, 0.0f, INFINITY);
        },
        [&](RTCRayHitN* packet, unsigned w, unsigned lane, int i) {
          if (RTCHitN_geomID(RTCRayHitN_HitN(packet, w), w, lane) != RTC_INVALID_GEOMETRY_ID)
            pass.depth[std::size_t(pixels[first + std::size_t(i)])] = RTCRayN_tfar(RTCRayHitN_RayN(packet, w), w, lane);
        });
  });
  pass.primary_rays = pixels.size();
  // The shadow rays, from the hits in tile order: traced as the renderer
  // traces them, batched after the camera rays that found their points.
  // Each starts back towards the camera by the renderer's shadow offset, as
  // it leaves a surface on the side that faces the viewer.
  std::vector<Vec3> starts;
  for (int pixel : pixels) {
    const double depth = pass.depth[std::size_t(pixel)];
    if (!std::isfinite(depth)) continue;
    const CameraRay r = camera_ray(pixel);
    starts.push_back(r.origin + (depth - offset) * r.direction);
  }
  pass.shadow_rays = starts.size();
  pass.shadow_seconds = over_groups(starts.size(), scratch, [&](FieldRayContext& context, std::size_t first, int count) {
    occluded_rays(
        scene, &context.embree, width, first_rays(count),
        [&](RTCRayN* packet, unsigned w, unsigned lane, int i) {
          set_embree_ray(packet, w, lane, unsigned(i), starts[first + std::size_t(i)], light, 0.0f, INFINITY,
                         RayScene::kShadowRayMask);
        },
        [](RTCRayN*, unsigned, unsigned, int) {});
  });
  return pass;
}

// The best of three runs, pass by pass.
template <class Trace>
Pass best_of_three(Trace&& trace) {
  Pass best = trace();
  for (int run = 0; run < 2; ++run) {
    const Pass again = trace();
    best.primary_seconds = std::min(best.primary_seconds, again.primary_seconds);
    best.shadow_seconds = std::min(best.shadow_seconds, again.shadow_seconds);
  }
  return best;
}

// Pixels where both passes met a surface or both met none.
double agreement(const Pass& a, const Pass& b) {
  std::size_t same = 0;
  for (std::size_t i = 0; i < a.depth.size(); ++i) same += std::isfinite(a.depth[i]) == std::isfinite(b.depth[i]);
  return 100.0 * double(same) / double(a.depth.size());
}

std::string short_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  return name.size() > 5 && name.substr(name.size() - 5) == ".toml" ? name.substr(0, name.size() - 5) : name;
}

void bench_scene(const EmbreeDevice& device, const std::string& path, int size) {
  const ColorManagement color("", "");
  auto prepare = [&](const char* blend) {
    std::vector<std::string> settings = {"render.width=" + std::to_string(size),
                                         "render.height=" + std::to_string(size), "render.samples=1",
                                         "glyphs.shape=\"ellipsoid\""};
    if (blend) settings.push_back(std::string("surface.blend=\"") + blend + "\"");
    return prepare_scene(load_scene(path, settings), color);
  };
  const std::unique_ptr<PreparedScene> own = prepare(nullptr), union_ = prepare("max");
  const Camera camera(own->camera, size, size);
  const Vec3 light = own->shading.light_from.normalized();
  const double offset = own->render.shadow_offset;

  const HardEllipsoids hard(device, union_->field);
  const Pass light_pass = best_of_three([&] { return trace_passes(hard.get(), device.packet_width(), camera, size, light, offset); });
  auto field_pass = [&](const PreparedScene& p) {
    const RayScene scene(device, p.field, p.trace, DrawnContext{});
    return best_of_three([&] { return trace_passes(scene.get(), scene.packet_width(), camera, size, light, offset); });
  };
  const Pass max_pass = field_pass(*union_);
  const Pass own_pass = field_pass(*own);

  const std::string name = short_name(path);
  auto row = [&](const char* geometry, const Pass& p, const char* note) {
    std::printf("%-28s %-22s %8zu %9.2f %9.2f %7.2f %7.2f  %s\n", name.c_str(), geometry, union_->field.sources.size(),
                p.primary_mrays(), p.shadow_mrays(), p.primary_mrays() / light_pass.primary_mrays(),
                p.shadow_mrays() / light_pass.shadow_mrays(), note);
  };
  char agree[64];
  std::snprintf(agree, sizeof agree, "agree %.2f %%", agreement(light_pass, max_pass));
  row("hard ellipsoids", light_pass, "");
  row("field, union (max)", max_pass, agree);
  row(own->field.blend == Blend::sum ? "field, blend (sum)" : "field, scene's (max)", own_pass, "");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int size = argc > 1 ? std::atoi(argv[1]) : 800;
  std::vector<std::string> scenes;
  for (int i = 2; i < argc; ++i) scenes.push_back(argv[i]);
  if (scenes.empty())
    for (const char* name : {"fig05_point_load_linear", "fig09_point_load_hyperstreamsurface", "fig14_dti_helix_glyphs"})
      scenes.push_back(std::string(HSB_SOURCE_DIR) + "/scenes/" + name + ".toml");
  const EmbreeDevice device;
  std::printf("%-28s %-22s %8s %9s %9s %7s %7s\n", "scene", "geometry", "sources", "primary", "shadow", "primary",
              "shadow");
  std::printf("%-28s %-22s %8s %9s %9s %7s %7s\n", "", "", "", "Mrays/s", "Mrays/s", "/light", "/light");
  for (const std::string& path : scenes) bench_scene(device, path, size);
  std::printf("(%d×%d, one camera ray through each pixel's centre, one shadow ray from each hit towards the key\n"
              " light, best of three, tracing only; /light: the rate as a fraction of the hard ellipsoids';\n"
              " targets: union ≥ 0.5, blend ≥ 0.25; agree: pixels the union and the ellipsoids both cover or\n"
              " both leave; %s)\n",
              size, size, device.describe().c_str());
  return 0;
}
