#include "renderer/render/camera_samples.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "renderer/render/sampling.h"
#include "renderer/surface/embree_ray.h"
#include "renderer/surface/ray_packets.h"

namespace hsb {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Occlusion rays of one packet of camera samples: each unblocked ray adds
// its weight to its sample's key or ambient visibility. Rays towards the
// key light leave nearby points in nearly one direction: they share BVH
// traversals as 16-ray packets. Ambient rays scatter over the hemisphere,
// where a packet's lanes would mostly wait for each other (twice as slow
// over fig06's cap): they go one at a time, or against a list of the
// sources around them (ambient_rays.h).
class OcclusionBatch {
 public:
  // `planes`: the tangent planes of the glyph hit the ray leaves, or nullptr.
  void add(const Vec3& origin, const Vec3& direction, double tfar, int lane, double weight, bool ambient,
           const SupportPlanes* planes) {
    (ambient ? ambient_ : key_).push_back({origin, direction, tfar, lane, weight, planes});
  }

  void trace(const RayScene& scene, SampleTracer& tracer, Visibility* visibility) {
    const auto start = Clock::now();
    FieldRayContext context(tracer.tracers, tracer.shadow_stats);
    trace_ambient(scene, tracer, visibility);
    context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    for (std::size_t first = 0; first < key_.size(); first += kMaxPacket) {
      const int count = int(std::min<std::size_t>(kMaxPacket, key_.size() - first));
      const Pending* batch = &key_[first];
      unsigned traceable = 0;
      for (int i = 0; i < count; ++i) {
        context.origin_planes[std::size_t(i)] = batch[i].planes;
        if (embree_can_trace(batch[i].origin, batch[i].direction, 0.0, batch[i].tfar))
          traceable |= 1u << i;
        else
          ++tracer.shadow_stats.untraceable_rays;  // unblocked, and said so
      }
      occluded_rays(
          scene.get(), &context.embree, scene.packet_width(), traceable,
          [&](RTCRayN* packet, unsigned width, unsigned lane, int i) {
            const Pending& r = batch[i];
            set_embree_ray(packet, width, lane, unsigned(i), r.origin, r.direction, 0.0f, float(r.tfar),
                           RayScene::kShadowRayMask);
          },
          [&](RTCRayN* packet, unsigned width, unsigned lane, int i) {
            if (RTCRayN_tfar(packet, width, lane) >= 0.0f) visibility[batch[i].lane].key += batch[i].weight;
          });
    }
    tracer.shadow_rays += unsigned(key_.size() + ambient_.size());
    tracer.shadow_seconds += seconds_since(start);
    key_.clear();
    ambient_.clear();
    crowd_sum_ = crowd_points_ = 0;
  }

  // A glyph hit that sends ambient rays: how many sources overlap there.
  void note_crowd(std::uint32_t crowd) {
    crowd_sum_ += crowd;
    ++crowd_points_;
  }

 private:
  void trace_ambient(const RayScene& scene, SampleTracer& tracer, Visibility* visibility) {
    rays_.clear();
    planes_.clear();
    for (const Pending& r : ambient_) {
      rays_.push_back({r.origin, r.direction, 0.0, r.tfar});
      planes_.push_back(r.planes);
    }
    const double crowd = crowd_points_ ? double(crowd_sum_) / double(crowd_points_) : 0.0;
    tracer.ambient.trace(scene, rays_, planes_, crowd, tracer.tracers, tracer.shadow_stats, blocked_);
    for (std::size_t i = 0; i < ambient_.size(); ++i)
      if (!blocked_[i]) visibility[ambient_[i].lane].ambient += ambient_[i].weight;
  }

  struct Pending {
    Vec3 origin, direction;
    double tfar;
    int lane;
    double weight;
    const SupportPlanes* planes;
  };
  std::vector<Pending> key_, ambient_;
  std::vector<RayInterval> rays_;
  std::vector<const SupportPlanes*> planes_;
  std::vector<std::uint8_t> blocked_;
  std::uint64_t crowd_sum_ = 0, crowd_points_ = 0;
};

// Point k of the n a camera sample takes, stratified over all the n·samples
// the pixel's camera samples take together.
void pixel_stratified(const CameraRayJob& job, SamplePurpose purpose, int k, int n, double& u, double& v) {
  const int index = int(job.sample) * n + k;
  stratified(index, n * int(job.samples), sample_key(job.pixel, 0, purpose, std::uint64_t(index)), u, v);
}

// Key-light shadow rays from `point` (whose visible side faces `facing`):
// light_samples directions over the light's disc, each worth an equal share.
void add_key_rays(const ShadingSpec& shading, const CameraRayJob& job, const Vec3& point, const Vec3& facing,
                  double offset, int lane, const SupportPlanes* planes, OcclusionBatch& batch) {
  const int n = std::max(1, shading.light_size > 0.0 ? shading.light_samples : 1);
  const double half_angle = 0.5 * shading.light_size * M_PI / 180.0;
  const Vec3 start = point + offset * facing;
  for (int k = 0; k < n; ++k) {
    double u, v;
    pixel_stratified(job, SamplePurpose::light, k, n, u, v);
    const Vec3 direction = half_angle > 0.0 ? in_cone(shading.light_from, half_angle, u, v)
                                            : Vec3(shading.light_from.normalized());
    if (direction.dot(facing) <= 0.0) continue;  // below the horizon: that part of the disc is hidden
    batch.add(start, direction, INFINITY, lane, 1.0 / n, false, planes);
  }
}

void add_ambient_rays(const ShadingSpec& shading, const CameraRayJob& job, const Vec3& point, const Vec3& facing,
                      double offset, int lane, const SupportPlanes* planes, OcclusionBatch& batch) {
  const int n = shading.ao_samples;
  const Vec3 start = point + offset * facing;
  for (int k = 0; k < n; ++k) {
    double u, v;
    pixel_stratified(job, SamplePurpose::ambient, k, n, u, v);
    batch.add(start, cosine_hemisphere(facing, u, v), shading.ao_distance, lane, 1.0 / n, true, planes);
  }
}

// The shell's layers between the camera and `depth`, composited front to
// back over `sample`. Opacity rises from shell_opacity facing the viewer to
// shell_edge_opacity at grazing angles, so the body's outline shows as an
// edge while glyphs inside stay visible.
void composite_shell(const RayScene& scene, const ShadingSpec& shading, const CameraRay& ray, CameraSample& sample) {
  constexpr std::size_t max_layers = 8;
  thread_local std::vector<ShellCrossing> layers;
  if (!embree_can_trace(ray.origin, ray.direction, 0.0, INFINITY)) return;  // counted with the camera ray
  scene.shell()->crossings(ray.origin, ray.direction, std::isinf(sample.depth) ? INFINITY : double(sample.depth),
                           max_layers, layers);
  const Vec3 key = shading.light_from.normalized();
  std::array<double, 3> sum{0, 0, 0};
  double transmittance = 1.0;
  for (const ShellCrossing& layer : layers) {
    const Vec3& n = layer.normal;
    const double facing = std::fabs(n.dot(ray.direction));
    const double grazing = std::pow(1.0 - facing, 3.0);
    const double alpha = shading.shell_opacity + (shading.shell_edge_opacity - shading.shell_opacity) * grazing;
    const double lit = shading.ambient + shading.light_intensity * std::fabs(n.dot(key)) + shading.fill_intensity * 0.5;
    for (int c = 0; c < 3; ++c)
      sum[std::size_t(c)] += transmittance * alpha * lit * shading.shell_color[std::size_t(c)] * shading.light_color[std::size_t(c)];
    transmittance *= 1.0 - alpha;
  }
  for (int c = 0; c < 3; ++c)
    sample.color[std::size_t(c)] = float(sum[std::size_t(c)] + transmittance * sample.color[std::size_t(c)]);
  sample.alpha = float(1.0 - transmittance * (1.0 - sample.alpha));
}

// What a ray that meets nothing sees: the background, or the ground
// plane's shadow over it. Returns true when the ground plane needs its
// shadow rays (then `ground` is the point).
bool background_sample(const ShadingSpec& shading, const CameraRayJob& job, CameraSample& out, Vec3& ground) {
  const bool transparent = shading.background_kind == BackgroundKind::transparent;
  const Rgb bg = background_at(shading, job.picture_v);
  out.color = transparent ? Rgb{0, 0, 0} : bg;
  out.alpha = transparent ? 0.0f : 1.0f;
  if (!shading.ground) return false;
  const CameraRay& r = job.ray;
  const double height = r.origin.z() - shading.ground_height;
  if (height <= 0.0 || r.direction.z() >= 0.0) return false;
  ground = r.origin + (-height / r.direction.z()) * r.direction;
  return true;
}

}  // namespace

void background_camera_samples(const ShadingSpec& shading, const CameraRayJob* jobs, int count, SampleTracer& tracer,
                               CameraSample* out) {
  Vec3 ground;
  for (int i = 0; i < count; ++i) {
    out[i] = CameraSample{};
    background_sample(shading, jobs[i], out[i], ground);
  }
  tracer.primary_rays += unsigned(count);
}

void trace_camera_samples(const RayScene& scene, const ShadingSpec& shading, double shadow_offset,
                          const CameraRayJob* jobs, int count, SampleTracer& tracer, CameraSample* out) {
  FieldRayContext context(tracer.tracers, tracer.stats);
  context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  context.hit_planes = tracer.hit_planes.data();
  struct PrimaryHit {
    unsigned geometry;
    float t;
    Vec3 normal;  // Embree's geometric normal, for the context geometry
  } primary[kMaxPacket];
  unsigned traceable = 0;
  for (int i = 0; i < count; ++i) {
    primary[i] = {RTC_INVALID_GEOMETRY_ID, INFINITY, Vec3::Zero()};
    if (embree_can_trace(jobs[i].ray.origin, jobs[i].ray.direction, 0.0, INFINITY))
      traceable |= 1u << i;
    else
      ++tracer.stats.untraceable_rays;  // sees the background, and said so
  }
  const auto primary_start = Clock::now();
  intersect_rays(
      scene.get(), &context.embree, scene.packet_width(), traceable,
      [&](RTCRayHitN* packet, unsigned width, unsigned lane, int i) {
        set_embree_ray(packet, width, lane, unsigned(i), jobs[i].ray.origin, jobs[i].ray.direction, 0.0f, INFINITY);
      },
      [&](RTCRayHitN* packet, unsigned width, unsigned lane, int i) {
        RTCHitN* hit = RTCRayHitN_HitN(packet, width);
        primary[i] = {RTCHitN_geomID(hit, width, lane), RTCRayN_tfar(RTCRayHitN_RayN(packet, width), width, lane),
                      Vec3(RTCHitN_Ng_x(hit, width, lane), RTCHitN_Ng_y(hit, width, lane),
                           RTCHitN_Ng_z(hit, width, lane))};
      });
  tracer.primary_seconds += seconds_since(primary_start);
  tracer.primary_rays += unsigned(count);

  // What each ray met, and the occlusion rays that shading it needs.
  enum class Met { nothing, ground, glyph, context_only };
  Met met[kMaxPacket];
  Vec3 facing[kMaxPacket], ground[kMaxPacket];
  Visibility visibility[kMaxPacket];
  OcclusionBatch batch;
  for (int i = 0; i < count; ++i) {
    const CameraRayJob& job = jobs[i];
    const CameraRay& ray = job.ray;
    CameraSample& s = out[i] = CameraSample{};
    const unsigned id = primary[i].geometry;
    if (id == RTC_INVALID_GEOMETRY_ID) {
      met[i] = background_sample(shading, job, s, ground[i]) ? Met::ground : Met::nothing;
      if (met[i] == Met::ground) {
        visibility[i].key = 0.0;
        add_key_rays(shading, job, ground[i], Vec3::UnitZ(), shadow_offset, i, nullptr, batch);
      }
      continue;
    }
    s.alpha = 1.0f;
    if (id != scene.field_id()) {
      // Box edges and trajectory tubes: round, lit by the key light alone.
      met[i] = Met::context_only;
      s.depth = primary[i].t;
      const Vec3 n = primary[i].normal.normalized();
      const Rgb& base = id == scene.box_id() ? shading.box_color : shading.trajectory_color;
      const double lit = id == scene.box_id()
                             ? 1.0
                             : 0.6 + 0.4 * std::max(0.0, facing_normal(n, -ray.direction).dot(shading.light_from.normalized()));
      for (int c = 0; c < 3; ++c) s.color[std::size_t(c)] = float(base[std::size_t(c)] * lit);
      continue;
    }
    met[i] = Met::glyph;
    ++tracer.stats.glyph_hits;
    const SurfaceSample& surface = context.surface[std::size_t(i)];
    const double t = context.t[std::size_t(i)];
    s.depth = float(t);
    s.normal = {float(surface.normal.x()), float(surface.normal.y()), float(surface.normal.z())};
    s.scalar = surface.scalar;
    s.id = std::int32_t(surface.source);
    const Vec3 x = ray.origin + t * ray.direction;
    const SupportPlanes* planes = &tracer.hit_planes[std::size_t(i)];
    facing[i] = facing_normal(surface.normal, -ray.direction);
    visibility[i] = {0.0, shading.ao_samples > 0 ? 0.0 : 1.0};
    // A side facing away from the key light is unlit whatever lies between.
    if (shading.shadows && facing[i].dot(shading.light_from.normalized()) > -std::sin(0.5 * shading.light_size * M_PI / 180.0))
      add_key_rays(shading, job, x, facing[i], shadow_offset, i, planes, batch);
    else if (!shading.shadows)
      visibility[i].key = 1.0;
    if (shading.ao_samples > 0) {
      add_ambient_rays(shading, job, x, facing[i], shadow_offset, i, planes, batch);
      batch.note_crowd(surface.crowd);
    }
  }
  batch.trace(scene, tracer, visibility);

  for (int i = 0; i < count; ++i) {
    CameraSample& s = out[i];
    if (met[i] == Met::glyph) {
      const SurfaceSample& surface = context.surface[std::size_t(i)];
      s.color = shade_surface(shading, surface.color, surface.normal, -jobs[i].ray.direction, visibility[i]);
    } else if (met[i] == Met::ground) {
      // Only the shadow shows: darker where the data hides the key light.
      const double shadow = shading.ground_shadow * (1.0 - visibility[i].key);
      if (shading.background_kind == BackgroundKind::transparent) {
        s.alpha = float(shadow);  // black, premultiplied: zero colour
      } else {
        for (float& c : s.color) c = float(c * (1.0 - shadow));
      }
    }
    if (scene.shell()) composite_shell(scene, shading, jobs[i].ray, s);
  }
}

}  // namespace hsb
