#pragma once
// The blob field seen along one ray: the sources whose support the ray
// crosses, the first crossing F(t) = C among them, and the surface's normal
// and colour there. Two ways to find the crossing:
//  - sphere tracing with the directional step bound of design §5 (segment
//    tracing specialised to metaballs), field_ray.cpp; any kernel;
//  - exactly, exact_crossing.cpp: between consecutive support endpoints F is
//    one polynomial in t for the polynomial kernels, whose first root is
//    isolated by Bernstein subdivision.

#include <array>
#include <vector>

#include "renderer/surface/blob_field.h"
#include "renderer/surface/field_bound.h"
#include "renderer/surface/ray_span.h"
#include "renderer/surface/span_bounds.h"
#include "renderer/surface/support_planes.h"
#include "renderer/surface/support_sweep.h"
#include "renderer/surface/trace_stats.h"

namespace hsb {

enum class Intersector { sphere, exact };

struct TraceSettings {
  Intersector intersector = Intersector::sphere;
  // Smallest step the tracer takes, in world units. A crossing that enters
  // and leaves the surface within this distance can be missed; every other
  // crossing is found and then refined to full precision.
  double min_step = 1e-6;
  // Guard against pathological grazing rays; a ray that needs more steps is
  // reported as a miss and counted in TraceStats::step_limit_hits.
  int max_steps = 200000;
};

// What a ray asks of the field: its first crossing (camera rays), or
// whether it crosses at all (shadow rays, which need no particular one).
enum class CrossingQuery { first, any };

struct SurfaceSample {
  Vec3 normal = Vec3::UnitZ();           // unit, pointing out of the surface
  std::array<float, 3> color{0, 0, 0};   // influence-weighted, scene-linear
  float scalar = 0.0f;                   // influence-weighted colour scalar
  std::uint32_t source = 0;              // the source contributing most
  std::uint32_t crowd = 0;               // how many sources contribute here
};

// Scratch space for one ray at a time (or, for rays walked side by side,
// one each); keep them per thread and reuse them so the hot loop never
// allocates.
class FieldRay {
 public:
  // The caller fills these with every source whose support the ray crosses
  // within [tmin, tmax], in any order, then calls first_crossing(). The
  // answers do not depend on the order, to the bit: every sum that reaches
  // them is taken in spatial rank order or is exact.
  std::vector<RaySpan> spans;

  // Returns the smallest t in [tmin, tmax] with F(t) ≥ C (the ray's first
  // entry into the surface), or a negative value when there is none, by the
  // method settings.intersector names. With CrossingQuery::any it returns
  // some t where F ≥ C, not necessarily the first, as soon as one is known.
  //
  // Every kernel is non-negative, so a single source whose own value
  // reaches C bounds the first crossing from above (and for `any` settles
  // the question); the walk stops there. Segments where the running bound
  // (field_bound.h) proves F < C are skipped without summing their sources,
  // so a ray through k supports costs about k log k, not k².
  //
  // The ray o + t d is the one the spans were computed for: shapes other
  // than the ellipsoid evaluate their own g along it (glyph_shape.h).
  double first_crossing(const BlobField& field, const Vec3& origin, const Vec3& direction, double tmin,
                        double tmax, const TraceSettings& settings, TraceStats& stats,
                        CrossingQuery query = CrossingQuery::first);

  //
  // With groups (BlobField::groups) each group's sum is a surface of its
  // own and the answer is the nearest of their first crossings; the spans
  // left are the group's that was hit.

  // first_crossing() in steps, for rays traced side by side
  // (BlobGeometry::first_crossings): a glyph shape's walk mostly waits on
  // its gauges, a batch of two or three glyphs a probe, and several rays'
  // probes fill one batch for what one ray's cost. start_crossing() takes
  // first_crossing()'s arguments; while it or resume_crossing() returns
  // true, the ray waits on the gauges of its gauge_samples(), whose u and
  // du/dt go into gauge_u() and gauge_rates() (shape_u_rates()), and then
  // resume_crossing() goes on. Once either returns false, crossing() is
  // what first_crossing() returns, to the bit.
  bool start_crossing(const BlobField& field, const Vec3& origin, const Vec3& direction, double tmin, double tmax,
                      const TraceSettings& settings, TraceStats& stats, CrossingQuery query = CrossingQuery::first);
  bool resume_crossing();
  double crossing() const { return call_.answer; }
  const ShapeSample* gauge_samples() const { return samples_.data(); }
  std::size_t gauge_count() const { return gauges_wanted_; }
  double* gauge_u() { return sample_u_.data(); }
  double* gauge_rates() { return sample_rate_.data(); }
  // The gauges it waits on, evaluated by the ray alone.
  void evaluate_gauges();

  // Normal and colour at ray parameter t; uses the spans of the last
  // first_crossing() call, which cover every source that is non-zero there.
  // For a shape other than the ellipsoid, `planes` (when given) gets each
  // of those sources' tangent plane there, for the occlusion rays that
  // leave the point.
  SurfaceSample surface_at(const BlobField& field, const Vec3& origin, const Vec3& direction, double t,
                           SupportPlanes* planes = nullptr) const;

  // The next first_crossing() is an `any` query for a ray that leaves the
  // surface `planes` describes (nullptr: one that does not), and starts
  // its walk from them (support_planes.h). Used by that call only.
  void leave_surface(const SupportPlanes* planes) { origin_planes_ = planes; }

 private:
  // The call in progress, from start_crossing() to crossing().
  struct Call {
    const BlobField* field = nullptr;
    Vec3 origin = Vec3::Zero(), direction = Vec3::Zero();
    double tmin = 0.0, tmax = 0.0;
    const TraceSettings* settings = nullptr;
    TraceStats* stats = nullptr;
    CrossingQuery query = CrossingQuery::first;
    std::size_t group = 0;       // with groups: groups_met_'s index of the group traced
    double best = -1.0;          // with groups: the nearest of their crossings so far
    std::uint8_t best_group = 0;
    double upper = -1.0;         // the walking group's single-source bound
    double answer = -1.0;
  };
  Call call_;
  // The call answered: `t`.
  bool answer(double t);
  // With groups: only the spans of `group` in `spans`.
  void take_group(std::uint8_t group);
  // With groups: each from groups_met_[first] on, until one waits on
  // gauges (true) or all are answered, the nearest kept.
  bool trace_groups_from(std::size_t first);
  // With groups: the crossing `t` of the group traced is kept if nearest;
  // true where that answers the call (an `any` query).
  bool group_answered(double t);
  // first_crossing() of one group's sources, the spans, below tmax: true
  // while its walk waits on gauges, else `t` is its crossing.
  bool start_group_crossing(double tmax, double& t);
  // The earliest entry into one source's own level surface in [tmin,
  // tmax] (F ≥ C there), or −1; the spans that begin beyond it dropped.
  double drop_spans_beyond_first_entry(const BlobField& field, double tmin, double tmax);
  // Every group's spans, and each one's group, while first_crossing()
  // takes the groups one at a time.
  std::vector<RaySpan> grouped_spans_;
  std::vector<std::uint8_t> group_of_, groups_met_;

  // For an `any` query, the first step at or above C is the answer.
  // `ends_on_surface`: F ≥ C at tmax is known (a single source's entry).
  double sphere_trace(const BlobField& field, double tmin, double tmax, bool ends_on_surface,
                      const TraceSettings& settings, TraceStats& stats, CrossingQuery query);
  // Exact for `wyvill` and `quartic` under blend = "sum", and for every
  // kernel under blend = "max" (a union of ellipsoids). Only crossings where
  // F − C changes sign count: a surface the ray merely touches is no hit.
  double exact_crossing(const BlobField& field, double tmin, double tmax, bool ends_on_surface, TraceStats& stats);

  // The walk over segments shared by both methods (support_sweep.h), with
  // the running bound kept up to date.
  void begin_segments(const BlobField& field, double tmin, double tmax, bool ends_on_surface);
  // The next segment [start, end] that may hold a crossing: at least one
  // active source, and F < C not proven. False when none is left.
  bool next_segment(const BlobField& field, double tmax, double& start, double& end, TraceStats& stats);

  // Each span's ray in its source's stored frame, q_s(t) = q0 + t v; only
  // for shapes other than the ellipsoid.
  // rate: σ√a, the most N ≤ u changes per unit along the ray (shape_trace.cpp: span_rate).
  struct ShapeRay {
    Vec3 q0, v;
    double rate;
    double u_floor;  // u ≥ u_floor from the ray's start on: a signed glyph's points' (point_floors), else 0
  };

  // Shapes other than the ellipsoid (shape_trace.cpp). Their g is not
  // quadratic along the ray; u = √g is convex along it.
  //  - Each span's ray in its source's stored frame (shape_rays_), and
  //    the spans (already narrowed to the boxes that hold the shapes'
  //    supports, ray_span.h) put in the order the ray enters them.
  void prepare_shape_rays(const BlobField& field, const Vec3& origin, const Vec3& direction);
  //  - The earliest exact entry into one source's own level surface u =
  //    √g_level in [tmin, tmax], or −1: Newton's method from each span's
  //    outer bound (the bounding ellipsoid's entry), nearest first, each
  //    span's ray made for it alone. Needs neither the spans in order nor
  //    their prepared rays: a union, and an `any` query that enters a
  //    source, are answered without them.
  double first_shape_entry(const BlobField& field, const Vec3& origin, const Vec3& direction, double g_level,
                           double tmin, double tmax, TraceStats& stats);
  //  - A signed glyph's points bound its u from below along the ray more
  //    tightly than its box and cylinder (glyph_shape.h: least_point_u):
  //    each pointed span's floor of u from tmin on, with the span's ray it
  //    made for it (point_rays_, which prepare_shape_rays() keeps: the
  //    floor for the proofs' rows, the ray for the probes), and `peaks`, the
  //    sum of the spans' peaks, lowered by them (peaks_ to match). Stops
  //    once the sum is below C, which settles the ray.
  double point_floors(const BlobField& field, const Vec3& origin, const Vec3& direction, double tmin, double peaks,
                      TraceStats& stats);
  //  - A span's ray in its source's stored frame.
  ShapeRay shape_ray(const BlobField& field, const RaySpan& span, const Vec3& origin, const Vec3& direction) const;
  //  - A probe: F at t, over the spans whose interval holds t; keeps each
  //    one's u and du/dt there for proven_below_until(), and F's slope
  //    dF/dt. Staged, then finished once its gauges are in
  //    (finish_probe(): F). A Probe::bound skips the sources whose last
  //    tangent rises from there on, adding K of that tangent's value
  //    instead: an upper bound of F (skipped_ lists what was skipped), and
  //    all the proofs after it need.
  enum class Probe { exact, bound };
  void stage_shape_probe(double t, Probe probe = Probe::exact);
  //  - What every probe does: the spans live at t, each one skipped with
  //    the bound k that skip_with(i, k) gives when it returns true, and
  //    its gauge staged otherwise.
  template <class SkipWith>
  void stage_probe(double t, SkipWith&& skip_with);
  //  - Moves the skipped terms into the idle lanes of the probe's one
  //    batch of gauges, where it has no more live sources than lanes.
  void fill_idle_lanes() const;
  //  - The last probe made exact: only the sources it skipped are
  //    staged, and F has the bits an exact probe there would give.
  void stage_completion();
  //  - The staged probe's terms from its gauges; F and dF/dt summed.
  double finish_probe();
  //  - An upper bound of span i's K over [from, s] (from within its
  //    interval) from what is known of it: its last tangent, or before
  //    that the most u can fall from its edge, and its bounding ellipsoid
  //    (span_bounds.h); bound_row() is what it knows.
  double term_bound(const BlobField& field, std::size_t i, double from, double s) const;
  SpanBoundRow bound_row(std::size_t i, double from) const;
  bool has_tangent(std::size_t i) const { return tangent_at_[i] >= spans[i].t0; }
  //  - The largest s ≤ tmax up to which F < C is proven from what the
  //    last probe found (to within a hundredth of the way, or
  //    min_step).
  double proven_below_until(const BlobField& field, double tmax, double min_step) const;
  //  - A probe at t from the tangent planes of the surface the ray leaves:
  //    every live span with a plane skipped, its term bounded by its
  //    plane's line, and only the others evaluated; an upper bound of F
  //    that stage_completion() makes exact.
  void stage_plane_probe(const SupportPlanes& planes, double t);
  //  - How far along the ray F would reach C at its slope where the last
  //    probe looked: Newton's step, shared by the proofs' first try and
  //    the walk's steps onto the surface. +∞ where F does not rise there.
  double newton_step(double c) const;
  //  - The first crossing in [tmin, tmax] by stepping from proof to proof.
  //    For an `any` query the first probe at or above C is the answer.
  //    start_walk() stages the first probe; walk() goes on from the staged
  //    probe (its gauges in, or none wanted) until a probe waits on gauges
  //    (true) or the walk has its answer `t` (false).
  bool start_walk(double tmin, double tmax, double& t);
  bool walk(bool gauges_in, double& t);
  //  - What the probe just finished, F there, was for: true where it
  //    staged the next one, false with the walk's answer `t`.
  bool walk_on(double f, double& t);
  //  - A proof from the walk's point, and the next probe staged beyond
  //    it, or the answer (−1: none before tmax).
  bool walk_step(double& t);
  //    The step's own probe, at walk_.next (true: staged).
  bool stage_step_probe();
  //  - The crossing inside a bracket F(lo) < C ≤ F(hi), hi the last probe,
  //    to the precision refine() gives, by Newton's method with the probes'
  //    slopes: the next probe staged, or the answer `t`.
  bool start_refinement(double lo, double hi, double f_lo, double f_hi, double& t);
  bool refine_on(double f, double& t);
  bool refine_step(double& t);
  // What the walk was doing when its probe was staged (a probe's
  // completion, stage_completion(), keeps its probe's stage).
  enum class WalkStage { first_probe, step_probe, lookahead, refinement };
  struct Walk {
    WalkStage stage = WalkStage::first_probe;
    double tmax = 0.0;
    double t = 0.0, f = 0.0;  // where the walk stands: F < C proven up to t
    double next = 0.0;        // the step's probe
    int steps = 0;
    // The refinement's bracket, [lo, hi] with F − C of e_lo < 0 ≤ e_hi,
    // and its last probe: where, F − C there and dF/dt.
    double lo = 0.0, hi = 0.0, e_lo = 0.0, e_hi = 0.0, at = 0.0, excess = 0.0, slope = 0.0, tolerance = 0.0;
    int tries = 0;
  };
  Walk walk_;

  double crowd_peak(double tmin, double last_peak) const;
  double value_at(const BlobField& field, double t, TraceStats& stats) const;
  double slope_bound_at(const BlobField& field, double t) const;
  double refine(const BlobField& field, double lo, double hi, double f_lo, double f_hi,
                TraceStats& stats) const;

  SupportSweep sweep_;
  FieldUpperBound bound_;
  std::vector<double> peaks_;  // each span's largest value on its interval
  bool quadric_ = true;  // the field's shape is the ellipsoid (shape_is_quadric)
  const SupportPlanes* origin_planes_ = nullptr;  // leave_surface()
  // Each span's ray (its rate from the start, q0 and v once it is first
  // evaluated: ray_made_), of the ray o + t d prepare_shape_rays() was given.
  mutable std::vector<ShapeRay> shape_rays_;
  mutable std::vector<std::uint8_t> ray_made_;
  Vec3 ray_origin_ = Vec3::Zero(), ray_direction_ = Vec3::Zero();
  // Each span's u and du/dt where a probe last evaluated it.
  mutable std::vector<double> u_, du_dt_;
  std::vector<ShapeRay> point_rays_;  // point_floors(), in the spans' order before prepare_shape_rays()
  // Where each span's u and du/dt were found (−∞ before its first).
  mutable std::vector<double> tangent_at_;
  mutable double probed_at_ = 0.0, probed_value_ = 0.0, probed_slope_ = 0.0;
  // The last probe's term of each live span (K, and dK/dt where evaluated)
  // and which of them it skipped (indices into live_ and live_terms_).
  // (Built in place by its constructor: a braced temporary copied in was
  // stored as two halves and read back whole, a store-forwarding stall that
  // cost a tenth of a superquadric render.)
  struct Term {
    Term(double k, double dk_dt) : value(k), slope(dk_dt) {}
    double value, slope;
  };
  mutable std::vector<Term> live_terms_;
  mutable std::vector<std::uint32_t> skipped_, evaluated_;
  // The live spans' terms at the probe's t listed by `terms` (indices into
  // live_), their gauges staged all at once (samples_); finish_terms()
  // keeps each one's u, du/dt and tangent.
  void stage_terms(const std::vector<std::uint32_t>& terms);
  void finish_terms();
  const std::vector<std::uint32_t>* staged_terms_ = nullptr;
  // How many gauges the staged terms wait on: 0 once they are in. (The
  // lists keep their length, so staging a probe constructs nothing.)
  std::size_t gauges_wanted_ = 0;
  // The staged gauges (gauge_samples()) and their answers, and
  // surface_at()'s scratch.
  mutable std::vector<ShapeSample> samples_;
  mutable std::vector<double> sample_u_, sample_rate_, sample_g_;
  mutable std::vector<Vec3> sample_gradients_;
  // F and dF/dt from live_terms_, in the spans' order.
  double sum_live_terms(const BlobField& field) const;
  // The spans whose interval holds where the last probe looked, and
  // the first that begins after it.
  mutable std::vector<std::uint32_t> live_;
  mutable std::size_t first_unbegun_ = 0;
  // Every span before it ended before the walk's last probe, where the
  // next probe looks from.
  std::size_t first_open_ = 0;
  // proven_below_until()'s scratch: the bound's rows and their values.
  mutable SpanBoundRows rows_;
  // prepare_shape_rays()'s scratch for putting the spans in order: each
  // span's key, one 128-bit integer ordered as (t0, rank) with the span's
  // index below it, so a step of the sort is one comparison, where a key
  // of three fields took two and a branch between them.
  __extension__ typedef unsigned __int128 SpanKey;
  std::vector<SpanKey> keys_;
  std::vector<RaySpan> sorted_spans_;
  // The length of the last step proven_below_until() proved: where the
  // next one's search starts.
  mutable double proof_step_ = 0.0;
  struct Entry {
    double t;            // where the ray enters the bounding ellipsoid's level surface
    std::uint32_t span;
  };
  std::vector<Entry> entries_;
  mutable std::vector<std::uint32_t> contributing_;  // surface_at()'s scratch
};

// Whether exact_crossing() handles this field.
bool exact_crossing_supported(KernelKind kernel, Blend blend, GlyphShape shape = GlyphShape::ellipsoid);

}  // namespace hsb
