#include "renderer/render/render_image.h"

#include <emmintrin.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <utility>

#include "renderer/render/camera_frustum.h"
#include "renderer/render/camera_samples.h"
#include "renderer/render/pixel_filter.h"
#include "renderer/render/sampling.h"
#include "renderer/surface/embree_ray.h"

namespace hsb {
namespace {

using Clock = std::chrono::steady_clock;

// Camera rays are traced a tile of pixels at a time, one packet per
// sub-pixel sample: neighbouring rays meet the same sources.
constexpr int kTile = 4;
static_assert(kTile * kTile == kMaxPacket, "a tile fills one ray packet");

// Rows of pixels made at a time. A band's pixels gather samples from
// kFilterReach rows above and below it, so the samples of a band and its
// margins are kept; the rows are traced once each.
constexpr int kBand = 16;

// The camera samples of a window of picture rows, kept in a ring, with
// each sample's filter taps.
class SampleRows {
 public:
  SampleRows(int width, int per_pixel, int rows)
      : width_(width), per_pixel_(per_pixel), rows_(rows),
        samples_(std::size_t(width) * std::size_t(per_pixel) * std::size_t(rows)) {
    // One sample a pixel stands at its centre: one set of taps serves all.
    if (per_pixel == 1) centred_ = filter_taps(0.5f, 0.5f);
    else taps_.resize(samples_.size());
  }
  CameraSample* pixel(int x, int y) { return &samples_[slot(x, y)]; }
  const FilterTaps* taps(int x, int y) const { return centred_ ? &*centred_ : &taps_[slot(x, y)]; }
  // Whether each sample has taps of its own (else one set serves all).
  bool taps_per_sample() const { return !centred_; }
  // Keeps the taps of sample k of pixel (x, y), at (sx, sy) within it.
  void set_taps(int x, int y, int k, float sx, float sy) {
    if (!centred_) taps_[slot(x, y) + std::size_t(k)] = filter_taps(sx, sy);
  }

 private:
  std::size_t slot(int x, int y) const {
    const std::size_t row = std::size_t(y % rows_);
    return (row * std::size_t(width_) + std::size_t(x)) * std::size_t(per_pixel_);
  }
  int width_, per_pixel_, rows_;
  std::vector<CameraSample> samples_;
  std::vector<FilterTaps> taps_;
  std::optional<FilterTaps> centred_;
};

// Where camera sample k of pixel (x, y) lies in the picture: stratified
// over the pixel, jittered by a hash of the pixel and the sample.
void sample_position(int x, int y, int width, int k, int per_pixel, double& sx, double& sy) {
  const std::uint64_t pixel = std::uint64_t(y) * std::uint64_t(width) + std::uint64_t(x);
  double u, v;
  stratified(k, per_pixel, sample_key(pixel, std::uint64_t(k), SamplePurpose::pixel, 0), u, v);
  sx = x + (per_pixel == 1 ? 0.5 : u);
  sy = y + (per_pixel == 1 ? 0.5 : v);
}

bool cancelled(const RenderSettings& settings) {
  return settings.cancel && settings.cancel->load(std::memory_order_relaxed);
}

// Traces the camera samples of picture rows [first, last). A tile that
// cannot see the scene's reach (camera_frustum.h) takes the background
// without tracing, where `untraced_background` allows.
void trace_rows(const RayScene& scene, const Camera& camera, const ShadingSpec& shading,
                const RenderSettings& settings, int first, int last, int per_pixel, bool untraced_background,
                SampleRows& rows, tbb::enumerable_thread_specific<SampleTracer>& tracers) {
  const int tiles_x = (settings.width + kTile - 1) / kTile;
  const int tiles_y = (last - first + kTile - 1) / kTile;
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles_x * tiles_y), [&](const tbb::blocked_range<int>& range) {
    SampleTracer& tracer = tracers.local();
    for (int tile = range.begin(); tile < range.end(); ++tile) {
      if (cancelled(settings)) return;
      const int tx = tile % tiles_x, ty = tile / tiles_x;
      int px[kMaxPacket], py[kMaxPacket], count = 0;
      for (int dy = 0; dy < kTile; ++dy)
        for (int dx = 0; dx < kTile; ++dx) {
          const int x = tx * kTile + dx, y = first + ty * kTile + dy;
          if (x >= settings.width || y >= last) continue;
          px[count] = x;
          py[count++] = y;
        }
      // Every sample of the tile lies within its pixels' rectangle.
      const bool traced = !untraced_background ||
                          rectangle_may_see(camera, px[0], py[0], px[count - 1] + 1, py[count - 1] + 1, scene.reach());
      double position_x, position_y;
      for (int k = 0; k < per_pixel; ++k) {
        CameraRayJob jobs[kMaxPacket];
        for (int i = 0; i < count; ++i) {
          double sx, sy;
          sample_position(px[i], py[i], settings.width, k, per_pixel, sx, sy);
          if (traced) jobs[i].ray = camera.ray(sx, sy);
          jobs[i].pixel = std::uint64_t(py[i]) * std::uint64_t(settings.width) + std::uint64_t(px[i]);
          jobs[i].sample = std::uint32_t(k);
          jobs[i].samples = std::uint32_t(per_pixel);
          jobs[i].picture_v = sy / settings.height;
        }
        CameraSample results[kMaxPacket];
        if (traced) trace_camera_samples(scene, shading, settings.shadow_offset, jobs, count, tracer, results);
        else background_camera_samples(shading, jobs, count, tracer, results);
        for (int i = 0; i < count; ++i) {
          CameraSample& stored = rows.pixel(px[i], py[i])[k] = results[i];
          sample_position(px[i], py[i], settings.width, k, per_pixel, position_x, position_y);
          stored.x = float(position_x - px[i]);  // within the pixel, where float keeps every bit
          stored.y = float(position_y - py[i]);
          rows.set_taps(px[i], py[i], k, stored.x, stored.y);
        }
      }
    }
  });
}

// Adds w times a sample's colour and alpha (side by side in CameraSample)
// to `sum`: two lanes of doubles each, in SSE2, which every x86-64 has.
// Each lane does what a scalar sum does (a product, then a sum), so the
// bits are those of summing the four one by one.
inline void add_weighted(const CameraSample& s, double w, __m128d sum[2]) {
  static_assert(offsetof(CameraSample, alpha) == offsetof(CameraSample, color) + 3 * sizeof(float));
  const __m128 v = _mm_loadu_ps(s.color.data());  // R, G, B, then alpha
  const __m128d weight = _mm_set1_pd(w);
  sum[0] = _mm_add_pd(sum[0], _mm_mul_pd(weight, _mm_cvtps_pd(v)));
  sum[1] = _mm_add_pd(sum[1], _mm_mul_pd(weight, _mm_cvtps_pd(_mm_movehl_ps(v, v))));
}

// A pixel's colour and alpha from the weighted sums of its samples and
// the sum of the weights. The filter's side lobes are negative: colour
// and coverage are kept in range.
inline void store_colour(const __m128d sum[2], double weight, float* color, float* alpha) {
  double rgba[4];
  _mm_storeu_pd(rgba, sum[0]);
  _mm_storeu_pd(rgba + 2, sum[1]);
  for (int c = 0; c < 3; ++c) color[c] = float(std::max(0.0, rgba[c] / weight));
  *alpha = float(std::clamp(rgba[3] / weight, 0.0, 1.0));
}

// A row of colour and alpha from one sample a pixel, at its centre, the
// film's usual case: the weights are every pixel's, found once, and away
// from the picture's edges every one applies. The sums run in the order
// gather_row's do, so the bits are the same.
void gather_centred_row(int y, const RenderSettings& settings, SampleRows& rows, Film& film) {
  constexpr int kSide = 2 * kFilterReach + 1;
  struct Tap {
    const CameraSample* row;  // the samples of the tap's row, at offset `dx` from the pixel
    int dx;
    double w;
  };
  const FilterTaps& taps = *rows.taps(0, 0);
  Tap list[kSide * kSide];
  int count = 0;
  bool every_row = true;
  for (int r = 0; r < kSide; ++r) {
    const int ny = y + r - kFilterReach;
    if (ny < 0 || ny >= settings.height) {
      every_row = false;
      continue;
    }
    for (int d = 0; d < kSide; ++d)
      if (const double w = taps.x[d] * taps.y[r]; w != 0.0) list[count++] = {rows.pixel(0, ny), d - kFilterReach, w};
  }
  float* out_color = film.at(Plane::color, 0, y);
  float* out_alpha = film.at(Plane::alpha, 0, y);
  for (int x = 0; x < settings.width; ++x) {
    __m128d lanes[2] = {_mm_setzero_pd(), _mm_setzero_pd()};  // R G, B alpha
    double weight = 0.0;
    if (every_row && x >= kFilterReach && x + kFilterReach < settings.width) {
      for (int i = 0; i < count; ++i) {
        add_weighted(list[i].row[x + list[i].dx], list[i].w, lanes);
        weight += list[i].w;
      }
    } else {
      for (int i = 0; i < count; ++i) {
        const int nx = x + list[i].dx;
        if (nx < 0 || nx >= settings.width) continue;
        add_weighted(list[i].row[nx], list[i].w, lanes);
        weight += list[i].w;
      }
    }
    store_colour(lanes, weight, out_color + 3 * x, out_alpha + x);
  }
}

// One row of the film from the samples around it, by each plane's rule.
// The rows a pixel gathers from are found once for the whole row; the
// planes of the surface (normal, scalar) are summed only when the film
// has them.
template <bool kSurfacePlanes>
void gather_row(int y, const RenderSettings& settings, int per_pixel, SampleRows& rows, Film& film) {
  constexpr int kRows = 2 * kFilterReach + 1;
  const CameraSample* sample_rows[kRows];
  const FilterTaps* tap_rows[kRows];
  for (int dy = -kFilterReach; dy <= kFilterReach; ++dy) {
    const int ny = y + dy;
    const bool inside = ny >= 0 && ny < settings.height;
    sample_rows[dy + kFilterReach] = inside ? rows.pixel(0, ny) : nullptr;
    tap_rows[dy + kFilterReach] = inside ? rows.taps(0, ny) : nullptr;
  }
  // A pixel's taps are per sample, or one set for all.
  const std::size_t tap_step = rows.taps_per_sample() ? std::size_t(per_pixel) : 0;
  float* out_color = film.at(Plane::color, 0, y);
  float* out_alpha = film.at(Plane::alpha, 0, y);
  for (int x = 0; x < settings.width; ++x) {
    __m128d lanes[2] = {_mm_setzero_pd(), _mm_setzero_pd()};  // R G, B alpha
    double weight = 0.0;
    double normal[3] = {0, 0, 0}, scalar = 0.0, hit_weight = 0.0;
    for (int r = 0; r < kRows; ++r) {
      if (!sample_rows[r]) continue;
      for (int dx = -kFilterReach; dx <= kFilterReach; ++dx) {
        const int nx = x + dx;
        if (nx < 0 || nx >= settings.width) continue;
        const CameraSample* samples = sample_rows[r] + std::size_t(nx) * std::size_t(per_pixel);
        const FilterTaps* taps = tap_rows[r] + std::size_t(nx) * tap_step;
        for (int k = 0; k < per_pixel; ++k) {
          const double w = taps[k].x[dx + kFilterReach] * taps[k].y[r];
          if (w == 0.0) continue;
          const CameraSample& s = samples[k];
          add_weighted(s, w, lanes);
          weight += w;
          if (!kSurfacePlanes || s.id < 0) continue;
          for (int c = 0; c < 3; ++c) normal[c] += w * s.normal[std::size_t(c)];
          scalar += w * s.scalar;
          hit_weight += w;
        }
      }
    }
    store_colour(lanes, weight, out_color + 3 * x, out_alpha + x);
    if (film.has(Plane::normal) && hit_weight > 0.0) {
      const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      float* n = film.at(Plane::normal, x, y);
      for (int c = 0; c < 3; ++c) n[c] = length > 0.0 ? float(normal[c] / length) : 0.0f;
    }
    if (film.has(Plane::scalar) && hit_weight > 0.0) *film.at(Plane::scalar, x, y) = float(scalar / hit_weight);

    // Depth and id from the pixel's own samples: the nearest hit, and the
    // source most of them hit (the first such in sample order on a tie).
    const CameraSample* own = sample_rows[kFilterReach] + std::size_t(x) * std::size_t(per_pixel);
    if (film.has(Plane::depth)) {
      float nearest = INFINITY;
      for (int k = 0; k < per_pixel; ++k) nearest = std::min(nearest, own[k].depth);
      *film.at(Plane::depth, x, y) = nearest;
    }
    if (film.has(Plane::id)) {
      std::int32_t best = -1;
      int best_count = 0;
      for (int k = 0; k < per_pixel; ++k) {
        if (own[k].id < 0) continue;
        int n = 0;
        for (int j = 0; j < per_pixel; ++j) n += own[j].id == own[k].id;
        if (n > best_count) best = own[k].id, best_count = n;
      }
      *film.at(Plane::id, x, y) = float(best);
    }
  }
}

}  // namespace

RenderOutput render_image(const RayScene& scene, const CameraSpec& camera_spec, const ShadingSpec& shading,
                          const RenderSettings& settings) {
  const auto start = Clock::now();
  const Camera camera(camera_spec, settings.width, settings.height);
  const int n = std::max(1, settings.samples);
  const int per_pixel = n * n;

  RenderOutput out{Film(settings.width, settings.height, settings.planes, settings.rows_done ? kBand : 0)};
  tbb::enumerable_thread_specific<SampleTracer> tracers;
  SampleRows rows(settings.width, per_pixel, kBand + 2 * kFilterReach);
  // Rays that cannot meet anything need no tracing, unless the ground
  // plane (whose shadow needs rays) or coordinates beyond what Embree
  // traces (such rays are counted as untraceable) are in the picture. The
  // picture's corner rays say it for all: the origins of the others lie
  // between theirs.
  bool untraced_background = !shading.ground;
  for (const auto& [x, y] : {std::pair{0, 0}, {settings.width, 0}, {0, settings.height}, {settings.width, settings.height}}) {
    const CameraRay corner = camera.ray(x, y);
    untraced_background = untraced_background && embree_can_trace(corner.origin, corner.direction, 0.0, INFINITY);
  }

  int traced = 0;  // rows [0, traced) have their samples
  for (int band = 0; band < settings.height; band += kBand) {
    const int band_end = std::min(settings.height, band + kBand);
    const int needed = std::min(settings.height, band_end + kFilterReach);
    if (traced < needed)
      trace_rows(scene, camera, shading, settings, traced, needed, per_pixel, untraced_background, rows, tracers);
    traced = needed;
    // The rows traced since a cancel are incomplete: none reaches the film.
    if (cancelled(settings)) throw RenderCancelled();
    const bool surface_planes = out.film.has(Plane::normal) || out.film.has(Plane::scalar);
    const bool colour_only = !surface_planes && !out.film.has(Plane::depth) && !out.film.has(Plane::id);
    tbb::parallel_for(band, band_end, [&](int y) {
      if (colour_only && !rows.taps_per_sample()) gather_centred_row(y, settings, rows, out.film);
      else if (surface_planes) gather_row<true>(y, settings, per_pixel, rows, out.film);
      else gather_row<false>(y, settings, per_pixel, rows, out.film);
    });
    if (settings.rows_done) settings.rows_done(out.film, band, band_end);
    if (settings.progress) settings.progress(double(band_end) / settings.height);
  }

  for (const SampleTracer& t : tracers) {
    out.stats += t.stats;
    out.shadow_stats += t.shadow_stats;
    out.primary_rays += t.primary_rays;
    out.shadow_rays += t.shadow_rays;
    out.primary_seconds += t.primary_seconds;
    out.shadow_seconds += t.shadow_seconds;
  }
  out.threads = std::max<int>(1, int(tracers.size()));
  out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return out;
}

}  // namespace hsb
