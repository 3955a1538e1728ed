#pragma once
// Counters that explain where render time goes (hsb render --stats).

#include <cstdint>

namespace hsb {

struct TraceStats {
  std::uint64_t field_rays = 0;       // rays that queried the blob field
  std::uint64_t span_queries = 0;     // span BVH traversals (one per window along a ray)
  std::uint64_t span_candidates = 0;  // influence boxes the traversals reached
  std::uint64_t spans = 0;            // source supports collected (per query window)
  std::uint64_t segments = 0;         // stretches between support endpoints walked
  std::uint64_t segments_skipped = 0; // of those, proven F < C by the running bound
  std::uint64_t field_evaluations = 0;  // F(t) evaluations (steps + refinement)
  std::uint64_t kernel_evaluations = 0; // single-source K evaluations inside them
  std::uint64_t step_limit_hits = 0;    // rays that gave up (counted as misses)
  std::uint64_t untraceable_rays = 0;   // beyond Embree's range (embree_can_trace): not traced
  std::uint64_t glyph_hits = 0;         // camera rays whose first hit is the glyph surface

  TraceStats& operator+=(const TraceStats& o) {
    field_rays += o.field_rays;
    span_queries += o.span_queries;
    span_candidates += o.span_candidates;
    spans += o.spans;
    segments += o.segments;
    segments_skipped += o.segments_skipped;
    field_evaluations += o.field_evaluations;
    kernel_evaluations += o.kernel_evaluations;
    step_limit_hits += o.step_limit_hits;
    untraceable_rays += o.untraceable_rays;
    glyph_hits += o.glyph_hits;
    return *this;
  }
};

}  // namespace hsb
