#pragma once
// The first crossing F(t) = C along a ray, found by sphere tracing with the
// directional step bound of design §5 (segment tracing specialised to
// metaballs), and the surface's normal and colour there.

#include <array>
#include <vector>

#include "renderer/surface/blob_field.h"
#include "renderer/surface/ray_span.h"
#include "renderer/surface/trace_stats.h"

namespace hsb {

struct TraceSettings {
  // Smallest step the tracer takes, in world units. A crossing that enters
  // and leaves the surface within this distance can be missed; every other
  // crossing is found and then refined to full precision.
  double min_step = 1e-6;
  // Guard against pathological grazing rays; a ray that needs more steps is
  // reported as a miss and counted in TraceStats::step_limit_hits.
  int max_steps = 200000;
};

struct SurfaceSample {
  Vec3 normal = Vec3::UnitZ();           // unit, pointing out of the surface
  std::array<float, 3> color{0, 0, 0};   // influence-weighted, scene-linear
};

// Scratch space for one ray at a time; keep one per thread and reuse it so
// the hot loop never allocates.
class SphereTracer {
 public:
  // The caller fills these with every source whose support the ray crosses
  // within [tmin, tmax] (in any order), then calls first_crossing().
  std::vector<RaySpan> spans;

  // Returns the smallest t in [tmin, tmax] with F(t) ≥ C (the ray's first
  // entry into the surface), or a negative value when there is none.
  double first_crossing(const BlobField& field, double tmin, double tmax,
                        const TraceSettings& settings, TraceStats& stats);

  // Normal and colour at ray parameter t; uses the spans of the last
  // first_crossing() call, which cover every source that is non-zero there.
  SurfaceSample surface_at(const BlobField& field, const Vec3& origin, const Vec3& direction,
                           double t) const;

 private:
  double value_at(const BlobField& field, double t, TraceStats& stats) const;
  double slope_bound_at(const BlobField& field, double t) const;
  double refine(const BlobField& field, double lo, double hi, double f_lo, double f_hi,
                TraceStats& stats) const;

  std::vector<std::uint32_t> active_;  // indices into spans
};

}  // namespace hsb
