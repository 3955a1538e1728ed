#include "renderer/surface/field_ray.h"

#include "renderer/surface/illinois.h"
#include "renderer/surface/single_source.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace hsb {

double FieldRay::value_at(const BlobField& field, double t, TraceStats& stats) const {
  const std::vector<std::uint32_t>& active = sweep_.active();
  ++stats.field_evaluations;
  stats.kernel_evaluations += active.size();
  double f = 0.0;
  for (std::uint32_t i : active) f = blended(field.blend, f, kernel_value(field.kernel, spans[i].g(t)));
  return f;
}

// An upper bound on dF/dt from t to the end of the current segment. On its
// support |d K(g(t))/dt| ≤ √a · max|dK/du|, because √g changes at rate at
// most √a. Only a source the ray is still approaching (t < t_c) can raise
// F: past t_c it only falls, whichever segment we are in, so dropping it
// keeps the bound valid for the rest of the ray: it is one-sided, which is
// all that stepping towards F = C from below needs.
double FieldRay::slope_bound_at(const BlobField& field, double t) const {
  double rate = 0.0;
  for (std::uint32_t i : sweep_.active()) {
    const RaySpan& s = spans[i];
    if (t >= s.t_c) continue;
    rate = blended(field.blend, rate, std::sqrt(s.a));
  }
  return rate * kernel_max_du_slope(field.kernel);
}

// The crossing inside a bracket F(lo) < C ≤ F(hi), to double precision
// (so it hardly depends on the bracket, which depends on how the ray was
// traced: alone or in a packet, on which instruction set).
double FieldRay::refine(const BlobField& field, double lo, double hi, double f_lo, double f_hi,
                        TraceStats& stats) const {
  const double c = field.isovalue;
  const double tolerance = 1e-14 * (std::fabs(lo) + std::fabs(hi)) + 1e-300;
  return illinois([&](double t) { return value_at(field, t, stats) - c; }, lo, hi, f_lo - c, f_hi - c,
                  tolerance, 0.0, 100);
}

// Where the peaks of the ray's sources lie on average, weighted by their
// height: a mean of fractions of [tmin, last_peak], summed in fixed point.
// Integer sums are exact, so the mean is the same to the bit in whatever
// order the spans were collected (BVH traversal order depends on the
// instruction set); a float sum's last bits would not be, and they would
// reach the picture through the crossing found below this bound.
double FieldRay::crowd_peak(double tmin, double last_peak) const {
  constexpr double unit = 0x1p40;  // each term ≤ 2⁴⁰: 2²³ of them fit in 64 bits
  const double length = last_peak - tmin;
  if (!(length > 0.0)) return tmin;
  // x in [0, 2⁴⁰] to the nearest integer (ties to even): adding 2⁵²
  // leaves no fraction bits, and taking it away again is exact. Plain
  // arithmetic, where llround is a library call a span.
  const auto fixed = [](double x) { return std::uint64_t((x + 0x1p52) - 0x1p52); };
  std::uint64_t height = 0, moment = 0;
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const double p = std::clamp(peaks_[i], 0.0, 1.0);
    height += fixed(p * unit);
    moment += fixed(p * std::clamp((peak_t(spans[i]) - tmin) / length, 0.0, 1.0) * unit);
  }
  if (height == 0) return tmin;
  return tmin + std::min(1.0, double(moment) / double(height)) * length;
}

namespace {
// A group's crossing from what its trace found below its single-source
// bound `upper` (−1 where none): short of the bound only by round-off,
// the bound itself is on the surface.
double walked_or_upper(double found, double upper) { return found >= 0.0 ? found : upper; }
}  // namespace

double FieldRay::first_crossing(const BlobField& field, const Vec3& origin, const Vec3& direction, double tmin,
                                double tmax, const TraceSettings& settings, TraceStats& stats,
                                CrossingQuery query) {
  for (bool waiting = start_crossing(field, origin, direction, tmin, tmax, settings, stats, query); waiting;
       waiting = resume_crossing())
    evaluate_gauges();
  return crossing();
}

void FieldRay::evaluate_gauges() {
  shape_u_rates(call_.field->shape, samples_.data(), int(gauges_wanted_), sample_u_.data(), sample_rate_.data());
}

bool FieldRay::start_crossing(const BlobField& field, const Vec3& origin, const Vec3& direction, double tmin,
                              double tmax, const TraceSettings& settings, TraceStats& stats, CrossingQuery query) {
  call_ = Call{&field, origin, direction, tmin, tmax, &settings, &stats, query};
  if (field.groups.empty()) {
    double t;
    return start_group_crossing(tmax, t) || answer(t);
  }
  // Each group's surface on its own, the nearest first crossing of any
  // (an `any` query: the first group that has one). A single source's
  // entry bounds the union's first crossing as it bounds its own group's,
  // so the spans beyond the earliest of all go first.
  drop_spans_beyond_first_entry(field, tmin, tmax);
  grouped_spans_.swap(spans);
  // The groups the ray meets (a few: the line families), in their order.
  group_of_.clear();
  groups_met_.clear();
  for (const RaySpan& s : grouped_spans_) {
    const std::uint8_t g = field.groups[s.source];
    group_of_.push_back(g);
    if (std::find(groups_met_.begin(), groups_met_.end(), g) == groups_met_.end()) groups_met_.push_back(g);
  }
  std::sort(groups_met_.begin(), groups_met_.end());
  return trace_groups_from(0);
}

bool FieldRay::resume_crossing() {
  double t;
  if (walk(true, t)) return true;
  t = walked_or_upper(t, call_.upper);
  if (call_.field->groups.empty()) return answer(t);
  return trace_groups_from(group_answered(t) ? groups_met_.size() : call_.group + 1);
}

bool FieldRay::answer(double t) {
  call_.answer = t;
  origin_planes_ = nullptr;  // this call's only
  return false;
}

void FieldRay::take_group(std::uint8_t group) {
  spans.clear();
  for (std::size_t i = 0; i < grouped_spans_.size(); ++i)
    if (group_of_[i] == group) spans.push_back(grouped_spans_[i]);
}

bool FieldRay::trace_groups_from(std::size_t first) {
  for (call_.group = first; call_.group < groups_met_.size(); ++call_.group) {
    take_group(groups_met_[call_.group]);
    double t;
    if (start_group_crossing(call_.best >= 0.0 ? call_.best : call_.tmax, t)) return true;
    if (group_answered(t)) break;
  }
  // surface_at() shades the group that was hit, from all of its spans.
  if (call_.best >= 0.0 && call_.best_group != groups_met_.back()) take_group(call_.best_group);
  return answer(call_.best);
}

bool FieldRay::group_answered(double t) {
  if (t >= 0.0 && (call_.best < 0.0 || t < call_.best)) call_.best = t, call_.best_group = groups_met_[call_.group];
  return call_.best >= 0.0 && call_.query == CrossingQuery::any;
}

double FieldRay::drop_spans_beyond_first_entry(const BlobField& field, double tmin, double tmax) {
  // The earliest entry into a single source's own level surface (for a
  // shape other than the ellipsoid, into the ball inside it that bounds
  // it, found without evaluating the shape): F ≥ C there whatever the
  // others add (single_source.h).
  const double g_level = level_g(field.kernel, field.isovalue);
  double upper = -1.0;
  for (const RaySpan& s : spans) {
    const double t = single_source_entry(s, inner_level_g(field, s.source, g_level), tmin, tmax);
    if (t >= 0.0 && (upper < 0.0 || t < upper)) upper = t;
  }
  // A span query stops collecting at such an entry (blob_geometry.cpp):
  // which sources whose boxes the ray enters beyond the earliest one it
  // holds depends on the order the traversal met them in. None of them is
  // non-zero before that entry, where the answer lies, so all are left
  // out, and the answer is the same to the bit however the spans were
  // gathered (a list, a traversal, any BVH width). (The entering source
  // itself is entered inside its box, and stays.)
  if (upper >= 0.0)
    spans.erase(std::remove_if(spans.begin(), spans.end(), [&](const RaySpan& s) { return s.box_t0 > upper; }),
                spans.end());
  return upper;
}

bool FieldRay::start_group_crossing(double tmax, double& t) {
  const BlobField& field = *call_.field;
  const Vec3 &origin = call_.origin, &direction = call_.direction;
  const double tmin = call_.tmin;
  const TraceSettings& settings = *call_.settings;
  TraceStats& stats = *call_.stats;
  const CrossingQuery query = call_.query;
  const auto answered = [&](double crossing) {
    t = crossing;
    return false;
  };
  quadric_ = shape_is_quadric(field.shape);
  point_rays_.clear();  // the last ray's
  stats.spans += spans.size();
  // Bounds from the sources one at a time, before anything is ordered: the
  // earliest single-source entry (first pass), then F at tmin (a ray that
  // starts inside the surface crosses at once) and the sum of each
  // source's largest value on the ray (from g_e, an upper bound for every
  // shape): when even that is below C, so is F.
  const double c = field.isovalue;
  const double g_level = level_g(field.kernel, c);
  double upper = drop_spans_beyond_first_entry(field, tmin, tmax);
  if (upper >= 0.0 && query == CrossingQuery::any) return answered(upper);  // an `any` query has its answer
  // The exact entry into a shape's own level surface, at or before the
  // ball's (or at the ball's, should round-off put Newton's a hair past),
  // found before the spans' peaks are summed or their rays made and put in
  // order, which it does not need. A blend's first crossing lies at or
  // before it, and the walk below finds that crossing with the same probes
  // whether or not it knows the entry (the same kernel evaluations on
  // fig05 and fig08), so the Newton iterations, one glyph at a time and a
  // twelfth of fig08's camera rays, are left out there.
  const auto exact_entry = [&] {
    return first_shape_entry(field, origin, direction, g_level, tmin, upper >= 0.0 ? upper : tmax, stats);
  };
  // A union: the earliest entry is the whole answer (an ellipsoid's is
  // the one above), and the sources' values at tmin and their peaks, which
  // bound a blend, are not needed.
  if (field.blend == Blend::max) {
    if (quadric_) return answered(upper);
    const double exact = exact_entry();
    return answered(exact >= 0.0 ? exact : upper);
  }
  double at_start = 0.0, peaks = 0.0, last_peak = tmin;
  peaks_.resize(spans.size());
  for (std::uint32_t i = 0; i < spans.size(); ++i) {
    const RaySpan& s = spans[i];
    // (Another shape's value at tmin is shape_trace's first probe.)
    if (quadric_ && s.t0 <= tmin) at_start += kernel_value(field.kernel, s.g(tmin));  // a sum: a union has its answer
    // (A shape's own lower bound of g, which may be tighter than g_e's.)
    peaks_[i] = kernel_value(field.kernel, quadric_ ? s.g(peak_t(s)) : s.least_lower_g());
    peaks += peaks_[i];
    last_peak = std::max(last_peak, peak_t(s));
  }
  stats.kernel_evaluations += 2 * spans.size();
  if (!quadric_) {
    // Blended sources whose peaks (upper bounds) sum below C
    // leave F below it: nothing of the shapes is needed. A signed glyph's
    // points bound it more tightly than its box, at a cost: asked only
    // where the box's sum does not settle the ray, and kept for the walk.
    if (upper < 0.0 && peaks >= c && field.shape == GlyphShape::signed_superquadric)
      peaks = point_floors(field, origin, direction, tmin, peaks, stats);
    if (upper < 0.0 && peaks < c) return answered(-1.0);
    // An `any` query ends at an exact entry.
    if (query == CrossingQuery::any) {
      const double exact = exact_entry();
      if (exact >= 0.0) return answered(exact);
    }
    prepare_shape_rays(field, origin, direction);
  }
  if (at_start >= c) return answered(tmin);
  if (peaks < c) return answered(-1.0);
  // A crowd of sources that no single one reaches C in (a blended cap)
  // is most likely to lift F over C where they peak together: F there,
  // if it is C or more, bounds the first crossing too.
  // (Not for another shape: its g costs tens of times the quadratic's, the
  // check paid off on about one ray in eight, and its proofs find such
  // crowds anyway. Nor where a single source's entry already bounds the
  // crossing: on fig09 the crowd's peak then came before it too seldom
  // to pay for the sums, 26.8 -> 25.6 kernel evaluations a camera ray
  // without it, the same segments walked.)
  if (quadric_ && upper < 0.0) {
    const double t_crowd = crowd_peak(tmin, last_peak);
    double f = 0.0;
    for (std::uint32_t i = 0; i < spans.size(); ++i)
      if (spans[i].t0 <= t_crowd && t_crowd <= spans[i].t1)
        f += kernel_value(field.kernel, spans[i].g(t_crowd));
    stats.kernel_evaluations += spans.size();
    if (f >= c) {
      if (query == CrossingQuery::any) return answered(t_crowd);
      upper = t_crowd;
    }
  }

  const double end = upper >= 0.0 ? upper : tmax;
  double found;
  if (!quadric_) {
    // The walk, which may wait on gauges; its answer goes through
    // resume_crossing(), or the line below.
    call_.upper = upper;
    if (start_walk(tmin, end, found)) return true;
  } else {
    // The exact intersector needs g quadratic along the ray.
    const bool ends_on_surface = upper >= 0.0;
    found = settings.intersector == Intersector::exact ? exact_crossing(field, tmin, end, ends_on_surface, stats)
                                                        : sphere_trace(field, tmin, end, ends_on_surface, settings,
                                                                       stats, query);
  }
  return answered(walked_or_upper(found, upper));
}

void FieldRay::begin_segments(const BlobField& field, double tmin, double tmax, bool ends_on_surface) {
  sweep_.begin(spans, tmin, tmax);
  bound_.reset(kernel_traits(field.kernel), spans, peaks_, tmin, ends_on_surface);
}

bool FieldRay::next_segment(const BlobField& field, double tmax, double& start, double& end, TraceStats& stats) {
  const auto entered = [&](std::uint32_t i) { bound_.add(spans[i]); };
  const auto left = [&](std::uint32_t i) { bound_.remove(spans[i]); };
  while (sweep_.next(tmax, start, end, entered, left)) {
    ++stats.segments;
    if (bound_.proves_rest_below(field.isovalue, start, spans, sweep_.active())) return false;
    if (bound_.proves_below(field.isovalue, start, end, spans, sweep_.active())) {
      ++stats.segments_skipped;
      continue;
    }
    // Sums over the active set in entry order: the answer must not depend
    // on the order of the walk's updates.
    sweep_.sort_active();
    return true;
  }
  return false;
}

double FieldRay::sphere_trace(const BlobField& field, double tmin, double tmax, bool ends_on_surface,
                              const TraceSettings& settings, TraceStats& stats, CrossingQuery query) {
  begin_segments(field, tmin, tmax, ends_on_surface);
  const double c = field.isovalue;
  int steps = 0;
  double start, end;
  while (next_segment(field, tmax, start, end, stats)) {
    double t = start;
    double f = value_at(field, t, stats);
    // F < C just before every segment (below it, F was either proven under
    // C or traced under it, or is zero), so this is the ray starting inside
    // the surface, or a crossing exactly on a segment boundary.
    if (f >= c) return t;
    // Within a segment the active set, and so the slope bound, is fixed.
    while (t < end) {
      if (++steps > settings.max_steps) {
        ++stats.step_limit_hits;
        return -1.0;
      }
      const double rate = slope_bound_at(field, t);
      double dt = rate > 0.0 ? (c - f) / rate : std::numeric_limits<double>::infinity();
      dt = std::max(dt, settings.min_step);
      const double t_next = std::min(t + dt, end);
      const double f_next = value_at(field, t_next, stats);
      if (f_next >= c) return query == CrossingQuery::any ? t_next : refine(field, t, t_next, f, f_next, stats);
      t = t_next;
      f = f_next;
    }
  }
  return -1.0;
}

SurfaceSample FieldRay::surface_at(const BlobField& field, const Vec3& origin, const Vec3& direction, double t,
                                   SupportPlanes* planes) const {
  const Vec3 x = origin + t * direction;
  Vec3 gradient = Vec3::Zero();
  double weight = 0.0, best = -1.0, scalar = 0.0;
  Vec3 color = Vec3::Zero();
  SurfaceSample sample;
  // The sources that reach x, summed in spatial rank order: the same bits
  // whatever order the spans were collected in. Another shape's support
  // is its span, narrowed to the box (ray_span.h): inside the bounding
  // ellipsoid but outside the box, a third of a superquadric hit's sources
  // on fig05 and fig08, it is 0, and evaluating it showed nothing.
  contributing_.clear();
  const bool boxed = !shape_is_quadric(field.shape);
  for (std::uint32_t i = 0; i < spans.size(); ++i)
    if (spans[i].g(t) < 1.0 + 1e-9 && (!boxed || (spans[i].t0 <= t && t <= spans[i].t1)))
      contributing_.push_back(i);  // the rest are zero at x
  // A union of ellipsoids is the surface of the source entered here alone,
  // the largest here: the smallest g by the spans' own quadratics (of
  // equals, the first in rank order). Only it is evaluated; the others
  // are counted. (A third of a union's tracing was finding it among all.)
  std::uint32_t union_crowd = 0;
  if (field.blend == Blend::max && shape_is_quadric(field.shape) && contributing_.size() > 1) {
    std::uint32_t entered = contributing_.front();
    for (const std::uint32_t i : contributing_) {
      const double g = spans[i].g(t), least = spans[entered].g(t);
      union_crowd += g < 1.0;
      if (g < least || (g == least && spans[i].rank < spans[entered].rank)) entered = i;
    }
    contributing_.assign(1, entered);
  }
  std::sort(contributing_.begin(), contributing_.end(),
            [&](std::uint32_t a, std::uint32_t b) { return spans[a].rank < spans[b].rank; });
  // q = W_s(x − c) for each; the shape gives g and ∇_q g (all at once: a
  // superquadric's gauges run in SIMD lanes), and ∇g = W_sᵀ ∇_q g.
  samples_.resize(contributing_.size());
  sample_g_.resize(contributing_.size());
  sample_gradients_.resize(contributing_.size());
  for (std::size_t k = 0; k < contributing_.size(); ++k) {
    const RaySpan& span = spans[contributing_[k]];
    const BlobSource& s = field.sources[span.source];
    samples_[k] = {&shape_params(field, span.source), scaled_offset(s, shape_matrix(s), x), Vec3::Zero()};
  }
  shape_g_gradients(field.shape, samples_.data(), int(samples_.size()), sample_g_.data(), sample_gradients_.data());
  const bool keep_planes = planes && boxed;  // in rank order, as contributing_
  if (keep_planes) {
    planes->at = x;
    planes->planes.clear();
  }
  for (std::size_t c = 0; c < contributing_.size(); ++c) {
    const RaySpan& span = spans[contributing_[c]];
    const BlobSource& s = field.sources[span.source];
    const double g = sample_g_[c];
    const Vec3 grad_g = shape_matrix(s).transpose() * sample_gradients_[c];
    // u = √g, ∇u = ∇g/2u (none at a glyph's centre, where u has no plane).
    if (keep_planes && g > 0.0) {
      const double u = std::sqrt(g);
      planes->planes.push_back({span.rank, u, grad_g / (2.0 * u)});
    }
    const double k = kernel_value(field.kernel, g);
    if (k <= 0.0) continue;
    ++sample.crowd;
    const Vec3 source_color(s.color[0], s.color[1], s.color[2]);
    const bool strongest = k > best;
    if (strongest) {
      best = k;
      sample.source = span.source;
    }
    if (field.blend == Blend::sum) {
      gradient += kernel_slope(field.kernel, g) * grad_g;
      color += k * source_color;
      scalar += k * double(s.scalar);
      weight += k;
    } else if (strongest) {
      // max blend: the surface is the union, so the winning source alone
      // defines normal, colour and scalar.
      gradient = kernel_slope(field.kernel, g) * grad_g;
      color = source_color;
      scalar = s.scalar;
      weight = 1.0;
    }
  }
  const double len = gradient.norm();
  // dK/dg < 0, so ∇F points inwards; the outward normal is −∇F/|∇F|.
  if (len > 0.0) sample.normal = -gradient / len;
  if (weight > 0.0) {
    color /= weight;
    scalar /= weight;
  }
  sample.color = {float(color[0]), float(color[1]), float(color[2])};
  sample.scalar = float(scalar);
  if (union_crowd > 0) sample.crowd = union_crowd;
  return sample;
}

}  // namespace hsb
