// The first crossing for glyph shapes other than the ellipsoid
// (glyph_shape.h): their g is not quadratic along a ray, so neither the
// exact intersector nor the running polynomial bound of F applies, and the
// bounding ellipsoid g_e ≤ g, which still gives every span and box, is too
// loose to prove much (a sharp glyph's is √3 times its size). What does
// hold is that each source's u = √g is convex along the ray (a norm of q):
//  - one source alone is entered exactly, by Newton's method from outside;
//  - from where u and du/dt are known, u lies above its tangent line, and
//    where they are not, u falls at most σ√a per unit from the 1 it has
//    where the ray enters its support; K falls as u grows, so both bound
//    each source's value ahead, and their sum bounds F. Stepping to where
//    that sum could first reach C, and looking again, walks past crowds of
//    sources far below their peaks in a few steps.
//  - a tangent bounds u along the whole ray, not only near where it was
//    taken: a source found past its closest approach is not evaluated
//    again while the walk goes on (it only falls), so each step costs the
//    sources still coming closer.
//  - the walk pauses at each probe's gauges (FieldRay::start_crossing):
//    a packet's rays walk side by side and share batches of gauges.

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/bit_cast.h"
#include "renderer/surface/field_ray.h"
#include "renderer/surface/single_source.h"
#include "renderer/surface/superquadric_gauge.h"

namespace hsb {

namespace {
// A source with a tangent whose bound stays below this share of C is not
// evaluated again at a probe: the proofs carry it by its tangent until it
// matters.
constexpr double kSliver = 1.0 / 32.0;

// An occlusion ray asks only whether F reaches C anywhere on it. Where a
// probe finds F this near C and rising, the walk stages its step's probe
// only after one this many of Newton's steps ahead, past the crossing
// where F bends away from its tangent (a sharp glyph's edge): F ≥ C
// there answers the ray. Approached from below, each probe closed about
// nine tenths of the gap left to C (fig17's beads as superquadrics: a
// shadow ray through a second bead took 9 probes, at 0.47, 0.61, 0.69,
// 0.95, 0.993, 0.9989, 0.9998, 0.99998 and 1.0001 of C). Twice the step,
// from 0.9 of C: 1.97 -> 1.82 field evaluations a shadow ray (960², one
// sample), −1.6 % of the render's instructions; from anywhere below C, or
// at 1.25 steps, fewer answered and more were spent.
constexpr double kLookaheadFrom = 0.9;
constexpr double kLookahead = 2.0;

// The most a span's superquadric gauge N changes per unit along the ray,
// σ√a: N is 1-Lipschitz in the glyph's own frame (glyph_shape.h), which
// the ray crosses at σ√a per unit. N, not u, because it is the lower bound
// before a span is evaluated that needs it (bound_row): u ≥ N, and N ≥ 1
// where the span begins, at the edge of its bounding ellipsoid, box or
// cylinder, each of which holds N ≤ 1. A signed glyph's cones make u's own
// constant L = 1.2 (ShapeParams::lipschitz), and a rate of Lσ√a let the
// bound fall a fifth faster than it can.
double span_rate(const BlobField& field, const RaySpan& span) {
  return std::sqrt(span.a) * double(shape_params(field, span.source).bound_scale);
}

// Whether a ray from `start` along `direction` never reaches u = u_level
// of the source of spatial rank `rank`, by that source's tangent plane at
// the hit the ray leaves: u lies above the plane everywhere (it is
// convex), and along the ray the plane starts above the level and rises.
// A signed glyph's surface at its points lies well inside the box and
// cylinder that settle most such sources (first_shape_entry), and a ray
// leaving it had Newton's method take a gauge only to find u rising: on
// fig17's beads as signed glyphs (960², 1 sample) the shadow rays sought
// 1.22 million exact entries and found 0.14 million (as superquadrics
// 0.29 and 0.11 million); with the planes, 2.45 -> 2.07 field evaluations
// a shadow ray (superquadrics 2.01 -> 1.96).
bool plane_keeps_out(const SupportPlanes& planes, std::uint32_t rank, const Vec3& start, const Vec3& direction,
                     double u_level) {
  const auto plane = std::lower_bound(planes.planes.begin(), planes.planes.end(), rank,
                                      [](const SupportPlanes::Plane& p, std::uint32_t r) { return p.rank < r; });
  if (plane == planes.planes.end() || plane->rank != rank) return false;
  return plane->gradient.dot(direction) >= 0.0 && plane->u + plane->gradient.dot(start - planes.at) > u_level;
}
}  // namespace

double FieldRay::point_floors(const BlobField& field, const Vec3& origin, const Vec3& direction, double tmin,
                              double peaks, TraceStats& stats) {
  point_rays_.resize(spans.size());
  // Until the sum is below C: that settles the ray, and a peak not
  // lowered is still an upper bound. (So where the ray goes on, every
  // pointed span has its ray and floor here.)
  for (std::uint32_t i = 0; i < spans.size() && peaks >= field.isovalue; ++i) {
    const RaySpan& span = spans[i];
    const ShapeParams& params = shape_params(field, span.source);
    if (!params.pointed) continue;
    ShapeRay& r = point_rays_[i] = shape_ray(field, span, origin, direction);
    const double u = r.u_floor = least_point_u(params, r.q0, r.v, std::max(span.t0, tmin), span.t1);
    const double peak = kernel_value(field.kernel, std::max(u * u, span.least_lower_g()));
    ++stats.kernel_evaluations;
    if (peak < peaks_[i]) peaks += peak - peaks_[i], peaks_[i] = peak;
  }
  return peaks;
}

FieldRay::ShapeRay FieldRay::shape_ray(const BlobField& field, const RaySpan& span, const Vec3& origin,
                                       const Vec3& direction) const {
  const BlobSource& source = field.sources[span.source];
  const Mat3 w = shape_matrix(source);
  return {scaled_offset(source, w, origin), w * direction, span_rate(field, span)};
}

void FieldRay::prepare_shape_rays(const BlobField& field, const Vec3& origin, const Vec3& direction) {
  const std::size_t count = spans.size();
  // In the order the ray enters them, ties in spatial rank order: every
  // sum over the spans is then the same to the bit whatever order the BVH
  // handed them over in, and a sum up to some t stops at the first span
  // that starts beyond it. The keys are sorted and the spans gathered. A
  // double's bits, the sign bit flipped (all of them for a negative one),
  // are ordered as the doubles are.
  // Each span's rate is needed by every proof, its ray only where it is
  // evaluated: a third of the spans never are (beyond a camera ray's hit,
  // or bounded all along), and their rays are not made.
  keys_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint64_t bits = bit_cast<std::uint64_t>(spans[i].t0 + 0.0);  // (−0 as +0)
    const std::uint64_t ordered = bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);
    keys_[i] = (SpanKey{ordered} << 64) | (std::uint64_t{spans[i].rank} << 32) | i;
  }
  std::sort(keys_.begin(), keys_.end());
  sorted_spans_.resize(count);
  for (std::size_t i = 0; i < count; ++i) sorted_spans_[i] = spans[std::uint32_t(keys_[i])];
  spans.swap(sorted_spans_);
  shape_rays_.resize(count);
  ray_made_.assign(count, 0);
  // A pointed span's ray and floor, where point_floors() made them, in the
  // spans' new order.
  const bool points = point_rays_.size() == count;
  for (std::size_t i = 0; i < count; ++i) {
    ShapeRay& r = shape_rays_[i];
    if (points && shape_params(field, spans[i].source).pointed) {
      r = point_rays_[std::uint32_t(keys_[i])];
      ray_made_[i] = 1;
    } else {
      r.u_floor = 0.0;
      r.rate = span_rate(field, spans[i]);
    }
  }
  first_open_ = 0;
  ray_origin_ = origin;
  ray_direction_ = direction;
  u_.assign(count, 1.0);
  du_dt_.assign(count, 0.0);
  tangent_at_.assign(count, -std::numeric_limits<double>::infinity());
  proof_step_ = 0.0;
}

double FieldRay::first_shape_entry(const BlobField& field, const Vec3& origin, const Vec3& direction,
                                   double g_level, double tmin, double tmax, TraceStats& stats) {
  // An occlusion ray leaving a glyph hit has the hit's tangent planes
  // (support_planes.h): a source whose plane keeps it out is not tried.
  const SupportPlanes* planes = call_.query == CrossingQuery::any ? origin_planes_ : nullptr;
  const Vec3 start = origin + tmin * direction;
  const double u_level = std::sqrt(g_level);
  // Entering the bounding ellipsoid's level surface g_e = g_level is the
  // earliest a shape's own (inside that one) can be entered.
  entries_.clear();
  for (std::uint32_t i = 0; i < spans.size(); ++i) {
    const double t = single_source_entry(spans[i], g_level, tmin, tmax);
    if (t >= 0.0 && !(planes && plane_keeps_out(*planes, spans[i].rank, start, direction, u_level)))
      entries_.push_back({t, i});
  }
  // Nearest first: a source whose outer entry is past the best exact entry
  // so far cannot improve on it. (The least exact entry is the same
  // whatever order equal outer entries come in.)
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
    return a.t < b.t || (a.t == b.t && a.span < b.span);
  });
  double upper = -1.0;
  for (const Entry& e : entries_) {
    if (upper >= 0.0 && e.t >= upper) break;
    // u is a norm, so the level surface u = u_level lies inside the
    // support's box and cylinder scaled by u_level (ray_span.h): a ray
    // that misses those, most of those that enter the loose bounding
    // ellipsoid, is settled without a gauge, and Newton starts where it
    // enters them. (On fig17, 3.97 -> 3.45 shape evaluations an occlusion
    // ray.)
    const std::uint32_t source = spans[e.span].source;
    const ShapeSupport support = source_support(field, source);
    RaySpan level;
    if (!ray_span(field.sources[source], source, 0, origin, direction, e.t, upper >= 0.0 ? upper : tmax, level,
                  {u_level * support.box, u_level * support.radius, support.axis}))
      continue;
    const ShapeRay r = shape_ray(field, spans[e.span], origin, direction);
    const double t = shape_entry(field.shape, shape_params(field, source), r.q0, r.v, u_level, level.t0, level.t1);
    ++stats.field_evaluations;
    if (t >= 0.0 && (upper < 0.0 || t < upper)) upper = t;
  }
  return upper;
}

template <class SkipWith>
void FieldRay::stage_probe(double t, SkipWith&& skip_with) {
  probed_at_ = t;
  live_.clear();
  live_terms_.clear();
  skipped_.clear();
  evaluated_.clear();
  std::size_t i = first_open_;
  for (; i < spans.size(); ++i) {
    const RaySpan& s = spans[i];
    if (t < s.t0) break;  // neither this span nor any after it has begun
    if (t > s.t1) continue;  // outside its support K is 0
    live_.push_back(std::uint32_t(i));
    double k;
    if (skip_with(i, k)) {
      skipped_.push_back(std::uint32_t(live_terms_.size()));
      live_terms_.emplace_back(k, 0.0);
      continue;
    }
    evaluated_.push_back(std::uint32_t(live_terms_.size()));
    live_terms_.emplace_back(0.0, 0.0);
  }
  first_unbegun_ = i;
  fill_idle_lanes();
  stage_terms(evaluated_);
  ++call_.stats->field_evaluations;
}

// The gauges run in batches of up to kGaugeLanes glyphs, and a probe with
// few live sources fills one only in part. The skipped terms go in beside
// the evaluated ones, and become exact, with fresh tangents. (Filling only
// the narrowest batch the evaluated terms need, superquadric_gauge.h, took
// more probes than it saved: on fig17's beads as superquadrics, 480², 5.68
// -> 5.83 a camera ray and 1 % more time.) A tangent taken near a source's closest
// approach hardly rises, and a walk past it and towards the next bead
// crept, its bound short of C by what the stale tangent added: on fig17
// (signed beads, 960², one sample) 6.94 -> 6.51 probes a camera ray. In a
// crowd (more live sources than lanes) the lanes' own bookkeeping cost
// more than the fresher tangents saved. With no more live sources than
// lanes, every skipped term fits beside the evaluated ones.
void FieldRay::fill_idle_lanes() const {
  if (evaluated_.empty() || live_.size() > kGaugeLanes) return;
  evaluated_.insert(evaluated_.end(), skipped_.begin(), skipped_.end());
  skipped_.clear();
}

void FieldRay::stage_shape_probe(double t, Probe probe) {
  const BlobField& field = *call_.field;
  stage_probe(t, [&](std::size_t i, double& k) {
    if (probe != Probe::bound) return false;
    // What the proofs already know of its value here. Not evaluated
    // again where its tangent rises from here on (past its closest
    // approach: the tangent bounds it for the rest of the ray) or bounds
    // its term to a sliver of C. A source without a tangent yet is
    // evaluated once, however small its bound: that bound, u falling at
    // its greatest rate from the support's edge, climbs so steeply that
    // a few such sources in a crowd held each proof to a short step, and
    // the walk crept towards the surface (on fig05 as superquadrics, 11.9
    // steps a camera ray's walk against 9.4 with a tangent for each, the
    // same gauges evaluated).
    if (!has_tangent(i)) return false;
    k = term_bound(field, i, t, t);
    return du_dt_[i] >= 0.0 || k <= kSliver * field.isovalue;
  });
}

void FieldRay::stage_terms(const std::vector<std::uint32_t>& terms) {
  // All at once: the shape's gauges run in SIMD lanes.
  const BlobField& field = *call_.field;
  staged_terms_ = &terms;
  gauges_wanted_ = terms.size();
  if (samples_.size() < terms.size()) samples_.resize(terms.size());  // (surface_at() sizes it too)
  if (sample_u_.size() < terms.size()) sample_u_.resize(terms.size()), sample_rate_.resize(terms.size());
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const std::uint32_t i = live_[terms[k]];
    if (!ray_made_[i]) {
      const ShapeRay made = shape_ray(field, spans[i], ray_origin_, ray_direction_);
      shape_rays_[i].q0 = made.q0, shape_rays_[i].v = made.v;  // its rate and floor (0) are in already
      ray_made_[i] = 1;
    }
    const ShapeRay& r = shape_rays_[i];
    samples_[k] = {&shape_params(field, spans[i].source), r.q0 + probed_at_ * r.v, r.v};
  }
}

void FieldRay::finish_terms() {
  const BlobField& field = *call_.field;
  const std::vector<std::uint32_t>& terms = *staged_terms_;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const std::uint32_t i = live_[terms[k]];
    const double u = sample_u_[k], g = u * u;
    u_[i] = u;
    du_dt_[i] = sample_rate_[k];
    tangent_at_[i] = probed_at_;
    // dK/dt = dK/dg · 2u du/dt.
    live_terms_[terms[k]] = {kernel_value(field.kernel, g), kernel_slope(field.kernel, g) * 2.0 * u * du_dt_[i]};
  }
  call_.stats->kernel_evaluations += terms.size();
  gauges_wanted_ = 0;
}

double FieldRay::finish_probe() {
  finish_terms();
  // A completion's terms were the skipped ones: none is skipped now.
  if (staged_terms_ == &skipped_) skipped_.clear();
  return sum_live_terms(*call_.field);
}

double FieldRay::sum_live_terms(const BlobField& field) const {
  // In the spans' order, whatever was evaluated when: a completed probe
  // has the bits of an exact one.
  double f = 0.0, slope = 0.0, largest = -1.0;
  for (const Term& term : live_terms_) {
    f = blended(field.blend, f, term.value);
    if (field.blend == Blend::sum) slope += term.slope;
    else if (term.value > largest) largest = term.value, slope = term.slope;
  }
  probed_value_ = f;
  probed_slope_ = slope;
  return f;
}

void FieldRay::stage_plane_probe(const SupportPlanes& planes, double t) {
  const BlobField& field = *call_.field;
  // The ray's point at t, from the hit the planes were taken at.
  const Vec3 offset = call_.origin + t * call_.direction - planes.at;
  // The spans live where the ray starts all begin there, so they come in
  // rank order, as the planes do: one pass pairs them. (Were they not, a
  // span would only miss its plane and be evaluated.)
  auto plane = planes.planes.begin();
  const auto no_plane = planes.planes.end();
  stage_probe(t, [&](std::size_t i, double& k) {
    while (plane != no_plane && plane->rank < spans[i].rank) ++plane;
    // Without a plane, nonzero at the ray's start but not at the hit (a
    // support's edge passing between them): the ray starts inside it,
    // where nothing but its value bounds it.
    if (plane == no_plane || plane->rank != spans[i].rank) return false;
    // Its plane along the ray, a tangent in all but name: u ≥ u0 + t' du/dt
    // for every t'.
    u_[i] = plane->u + plane->gradient.dot(offset);
    du_dt_[i] = plane->gradient.dot(call_.direction);
    tangent_at_[i] = t;
    k = term_bound(field, i, t, t);
    return true;
  });
}

void FieldRay::stage_completion() { stage_terms(skipped_); }

namespace {
// How near the refinement brings a crossing in [lo, hi]: the bracket's
// width at the end, or Newton's correction from the probe on its far
// side. 2·10⁻¹⁰ of the distance along the ray is under a millionth of a
// pixel at a 30° field 1000 pixels wide, and under a hundred-thousandth
// of the shadow rays' offset (render.shadow_offset, a tenth of a pixel);
// it lets the probe that Newton's method lands just past the crossing end
// the refinement (refine_step), where 10⁻¹⁴ took one more from the other
// side (fig17's beads as superquadrics, 960², one sample: 5.68 -> 4.80
// field evaluations a camera ray, the picture the same to the byte).
double crossing_tolerance(double lo, double hi) { return 1e-10 * (std::fabs(lo) + std::fabs(hi)) + 1e-300; }
}  // namespace

// Newton's method on F − C inside the bracket, with dF/dt from the probe:
// F is smooth where it crosses C, so from a bracket a step of the proofs
// wide it settles in a few probes where the Illinois method (refine())
// takes about ten, each a probe of every live source. Each estimate is
// nudged a quarter of the tolerance past the root, to the side the last
// probe was not on, so the bracket closes from both sides instead of
// Newton's one; a step that leaves the bracket, or a slope of the wrong
// sign, falls back to the bracket's secant.
bool FieldRay::start_refinement(double lo, double hi, double f_lo, double f_hi, double& t) {
  const double c = call_.field->isovalue;
  Walk& w = walk_;
  w.lo = lo, w.hi = hi, w.e_lo = f_lo - c, w.e_hi = f_hi - c;
  w.tolerance = crossing_tolerance(lo, hi);
  // The last probe: where, how far above C, and F's slope there.
  w.at = hi, w.excess = w.e_hi, w.slope = probed_at_ == hi ? probed_slope_ : 0.0;
  w.tries = 0;
  return refine_step(t);
}

bool FieldRay::refine_step(double& t) {
  Walk& w = walk_;
  // Settled where the last probe is at or past C and Newton's step back
  // from it is within the tolerance: the crossing is that near, on F ≥ C.
  const bool settled = w.excess >= 0.0 && w.slope > 0.0 && w.excess <= w.slope * w.tolerance;
  if (!(w.tries < 100 && w.hi - w.lo > w.tolerance && w.e_hi > 0.0) || settled) {
    t = w.hi;
    return false;
  }
  double s = (w.lo * w.e_hi - w.hi * w.e_lo) / (w.e_hi - w.e_lo);
  if (w.slope > 0.0) {
    const double newton = w.at - w.excess / w.slope + (w.excess >= 0.0 ? -0.25 : 0.25) * w.tolerance;
    if (newton > w.lo && newton < w.hi) s = newton;
  }
  if (!(s > w.lo && s < w.hi)) s = 0.5 * (w.lo + w.hi);
  w.at = s;
  w.stage = WalkStage::refinement;
  stage_shape_probe(s);
  return true;
}

bool FieldRay::refine_on(double f, double& t) {
  Walk& w = walk_;
  w.excess = f - call_.field->isovalue;
  w.slope = probed_slope_;
  if (w.excess >= 0.0) w.hi = w.at, w.e_hi = w.excess;
  else w.lo = w.at, w.e_lo = w.excess;
  ++w.tries;
  return refine_step(t);
}

double FieldRay::newton_step(double c) const {
  return probed_slope_ > 0.0 ? (c - probed_value_) / probed_slope_ : std::numeric_limits<double>::infinity();
}

// Inlined: the proofs build tens of rows each, and the call cost as much
// as the row.
[[gnu::always_inline]] inline SpanBoundRow FieldRay::bound_row(std::size_t i, double from) const {
  const RaySpan& span = spans[i];
  // Not yet evaluated, u ≥ N ≥ 1 at the support's edge t0, and N changes
  // at most σ√a per unit (span_rate); convex, so above its tangent where it
  // was last evaluated, which is lowest at the interval's end it falls
  // towards (its end if it falls, `from` if it rises). And g is at least
  // the span's lower bound, the bounding ellipsoid's g_e or what the box or
  // cylinder says (RaySpan::lower_a), smallest nearest its vertex. And u
  // is at least the floor a signed glyph's points give it (point_floors).
  SpanBoundRow r{span.t1,      1.0,          -shape_rays_[i].rate, span.t0, std::max(span.lower_t, from),
                 span.lower_t, span.lower_a, span.lower_g, shape_rays_[i].u_floor};
  if (has_tangent(i)) {
    if (du_dt_[i] < 0.0) r.u0 = u_[i], r.rate = du_dt_[i], r.tau = tangent_at_[i];
    else r.u0 = u_[i] + du_dt_[i] * (from - tangent_at_[i]), r.rate = 0.0, r.tau = 0.0;
  }
  return r;
}

[[gnu::always_inline]] inline double FieldRay::term_bound(const BlobField& field, std::size_t i, double from,
                                                           double s) const {
  return span_bound(bound_row(i, from), s, field.kernel);
}

double FieldRay::proven_below_until(const BlobField& field, double tmax, double min_step) const {
  const double t = probed_at_, c = field.isovalue;
  // F is a sum here: a union's crossing is its first entry, which
  // start_group_crossing() finds without a walk.
  // A span live at t that is past its closest approach by both its
  // tangent and its lower bound's vertex has its largest value at t, whatever
  // s: those are summed once. The others are rows of the bound, from t.
  double fixed = 0.0;
  rows_.clear();
  for (std::uint32_t i : live_) {
    if (has_tangent(i) && du_dt_[i] >= 0.0 && spans[i].lower_t <= t)
      fixed += term_bound(field, i, t, t);
    else rows_.push(bound_row(i, t));
  }
  const std::size_t rising = rows_.size();
  // An upper bound of F over [t, s]: each source's largest value there,
  // at most its peak on the ray. It never falls as s grows. The spans in
  // their order: those live at t, then those begun by s, each a row from
  // where it begins, added as the tries first reach it.
  std::size_t next = first_unbegun_;
  const auto bound = [&](double s) {
    for (; next < spans.size() && spans[next].t0 <= s; ++next) rows_.push(bound_row(next, spans[next].t0));
    std::size_t count = rows_.size();
    while (count > rising && spans[first_unbegun_ + (count - rising) - 1].t0 > s) --count;
    return fixed + span_bounds_sum(rows_, count, s, field.kernel);
  };
  // Out by doubling steps to the first s the bound does not clear (a sum
  // up to s costs only the spans begun by s, so the short tries are
  // cheap), then the Illinois method on the bound's excess over C, e(lo) <
  // 0 ≤ e(hi) (regula falsi, halving the weight of an end kept twice):
  // within a hundredth of the way is far enough. Before any try, F at t
  // stands in for the bound there. The first step is where F would reach
  // C at its slope at t, where it rises (the bound rises at least as
  // steeply, so that step mostly lands just past the bound's crossing, and
  // the bracket is tight from the start: on fig17's beads 5.0 -> 4.5 tries
  // a proof), else the last proof's length. With no live source still
  // rising, the bound stays `fixed` until the next source begins: the
  // steps start there.
  double lo = t, hi = tmax, e_lo = probed_value_ - c, e_hi = 0.0;
  double first_step = probed_slope_ > 0.0 ? newton_step(c) : proof_step_;
  if (rising == 0 && fixed < c) {
    if (first_unbegun_ == spans.size()) return tmax;
    lo = std::min(spans[first_unbegun_].t0, tmax);
    e_lo = fixed - c;
    first_step = proof_step_;
  }
  for (double step = std::max({first_step, min_step, lo - t}); lo < tmax; step *= 2.0) {
    const double s = std::min(lo + step, tmax);
    const double e = bound(s) - c;
    if (e >= 0.0) {
      hi = s;
      e_hi = e;
      break;
    }
    lo = s;
    e_lo = e;
  }
  if (lo >= tmax) return tmax;
  for (int i = 0, side = 0; i < 40 && hi - lo > std::max(0.01 * (lo - t), min_step); ++i) {
    double s = (lo * e_hi - hi * e_lo) / (e_hi - e_lo);
    if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
    const double e = bound(s) - c;
    if (e < 0.0) {
      lo = s;
      e_lo = e;
      if (side == -1) e_hi *= 0.5;
      side = -1;
    } else {
      hi = s;
      e_hi = e;
      if (side == 1) e_lo *= 0.5;
      side = 1;
    }
  }
  proof_step_ = lo - t;
  return lo;
}

bool FieldRay::start_walk(double tmin, double tmax, double& t) {
  Walk& w = walk_;
  // Past the last support F is 0: the search for a proof stays short of it.
  double last = tmin;
  for (const RaySpan& s : spans) last = std::max(last, s.t1);
  w.tmax = std::min(tmax, last);
  w.t = tmin;
  w.steps = 0;
  w.stage = WalkStage::first_probe;
  // An occlusion ray that leaves a glyph hit starts from the hit's planes;
  // only if they do not keep F below C at its start is anything evaluated.
  if (origin_planes_ && call_.query == CrossingQuery::any) stage_plane_probe(*origin_planes_, tmin);
  else stage_shape_probe(tmin);
  return walk(false, t);
}

bool FieldRay::walk(bool gauges_in, double& t) {
  for (;; gauges_in = false) {
    if (gauges_wanted_ && !gauges_in) return true;
    if (!walk_on(finish_probe(), t)) return false;
  }
}

bool FieldRay::walk_on(double f, double& t) {
  const double c = call_.field->isovalue;
  Walk& w = walk_;
  if (w.stage == WalkStage::refinement) return refine_on(f, t);
  // At or above C by the bound: the terms it skipped decide. (The
  // completion comes back here with none skipped, its F exact.)
  if (f >= c && !skipped_.empty()) {
    stage_completion();
    return true;
  }
  if (w.stage == WalkStage::lookahead) {
    // F ≥ C there answers an occlusion ray; else the step's own probe.
    if (f >= c) {
      t = probed_at_;
      return false;
    }
    return stage_step_probe();
  }
  if (w.stage == WalkStage::first_probe) {
    if (f >= c) {
      t = w.t;
      return false;
    }
    w.f = f;
    return walk_step(t);
  }
  if (f >= c) {
    if (call_.query == CrossingQuery::any) {
      t = w.next;
      return false;
    }
    return start_refinement(w.t, w.next, w.f, f, t);
  }
  w.t = w.next;
  w.f = f;
  // No probe goes back before t: the spans in front that ended before
  // it are not looked at again.
  while (first_open_ < first_unbegun_ && spans[first_open_].t1 < w.t) ++first_open_;
  return walk_step(t);
}

bool FieldRay::walk_step(double& t) {
  const double c = call_.field->isovalue;
  const TraceSettings& settings = *call_.settings;
  Walk& w = walk_;
  // Where F at its slope reaches C within min_step, the walk is on the
  // surface: a proof would reach no further than the min_step it steps
  // unproven anyway (TraceSettings::min_step), and is left out. Nearly
  // every walk that meets the surface ended with such a proof (on fig17's
  // beads as superquadrics, 960², 1 sample: all but 130 of 509,977
  // camera rays' and 108 of 189,083 occlusion rays'; 8% of the proofs).
  const double newton = newton_step(c);
  const bool at_surface = newton < settings.min_step;
  const double reach = at_surface ? w.t : proven_below_until(*call_.field, w.tmax, settings.min_step);
  if (reach >= w.tmax) {
    t = -1.0;
    return false;
  }
  if (++w.steps > settings.max_steps) {
    ++call_.stats->step_limit_hits;
    t = -1.0;
    return false;
  }
  w.next = std::min(std::max(reach, w.t + settings.min_step), w.tmax);
  // There a camera ray steps by Newton's method instead, a quarter of
  // the refinement's tolerance past its estimate: from a probe that near,
  // the estimate is within the tolerance, so the probe lands just past C
  // and one more closes the bracket, where a min_step past C took three
  // (on fig17's beads 6.47 -> 5.67 probes a camera ray). An occlusion
  // ray keeps the min_step, which lands past C surely and answers it.
  if (at_surface && call_.query == CrossingQuery::first)
    w.next = std::min(w.next, w.t + newton + 0.25 * crossing_tolerance(w.t, w.t));
  if (call_.query == CrossingQuery::any && !at_surface && probed_slope_ > 0.0 &&
      probed_value_ >= kLookaheadFrom * c) {
    const double ahead = w.t + kLookahead * newton;
    if (ahead > w.next && ahead < w.tmax) {
      w.stage = WalkStage::lookahead;
      stage_shape_probe(ahead, Probe::bound);
      return true;
    }
  }
  return stage_step_probe();
}

bool FieldRay::stage_step_probe() {
  walk_.stage = WalkStage::step_probe;
  stage_shape_probe(walk_.next, Probe::bound);
  return true;
}

}  // namespace hsb
