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

#include <algorithm>
#include <cmath>

#include "renderer/surface/field_ray.h"

namespace hsb {

void FieldRay::prepare_shape_rays(const BlobField& field, const Vec3& origin, const Vec3& direction) {
  // The ray in a source's stored frame: made again for each span kept
  // once they are sorted, which costs no more than carrying it through
  // the sort (nine loads and two products).
  const auto ray_of = [&](const RaySpan& s) {
    const BlobSource& source = field.sources[s.source];
    const Mat3 w = shape_matrix(source);
    return ShapeRay{scaled_offset(source, w, origin), w * direction};
  };
  std::size_t kept = 0;
  for (std::size_t i = 0; i < spans.size(); ++i) {
    RaySpan s = spans[i];
    const ShapeRay r = ray_of(s);
    if (!clip_to_shape_box(shape_params(field, s.source), r.q0, r.v, s.t0, s.t1)) continue;
    spans[kept++] = s;
  }
  spans.resize(kept);
  // In the order the ray enters them, ties in spatial rank order: every
  // sum over the spans is then the same to the bit whatever order the BVH
  // handed them over in, and a sum up to some t stops at the first span
  // that starts beyond it.
  std::sort(spans.begin(), spans.end(),
            [](const RaySpan& a, const RaySpan& b) { return a.t0 < b.t0 || (a.t0 == b.t0 && a.rank < b.rank); });
  shape_rays_.clear();
  for (const RaySpan& s : spans) shape_rays_.push_back(ray_of(s));
  u_.assign(kept, 1.0);
  du_dt_.assign(kept, 0.0);
  proof_step_ = 0.0;
}

double FieldRay::first_shape_entry(const BlobField& field, double g_level, double tmax, TraceStats& stats) {
  // Nearest first: a source whose outer entry is past the best exact entry
  // so far cannot improve on it.
  std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
    return a.t < b.t || (a.t == b.t && a.span < b.span);
  });
  const double u_level = std::sqrt(g_level);
  double upper = -1.0;
  for (const Entry& e : entries_) {
    if (upper >= 0.0 && e.t >= upper) break;
    const ShapeRay& r = shape_rays_[e.span];
    const double t = shape_entry(field.shape, shape_params(field, spans[e.span].source), r.q0, r.v, u_level, e.t,
                                 upper >= 0.0 ? upper : tmax);
    ++stats.field_evaluations;
    if (t >= 0.0 && (upper < 0.0 || t < upper)) upper = t;
  }
  return upper;
}

double FieldRay::shape_value_at(const BlobField& field, double t, TraceStats& stats) const {
  probed_at_ = t;
  double f = 0.0;
  std::size_t covering = 0;
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const RaySpan& s = spans[i];
    if (t < s.t0) break;  // neither this span nor any after it has begun
    if (t > s.t1) continue;  // outside its support K is 0
    const ShapeRay& r = shape_rays_[i];
    const double u = shape_u_rate(field.shape, shape_params(field, s.source), r.q0 + t * r.v, r.v, du_dt_[i]);
    u_[i] = u;
    f = blended(field.blend, f, kernel_value(field.kernel, u * u));
    ++covering;
  }
  ++stats.field_evaluations;
  stats.kernel_evaluations += covering;
  return f;
}

double FieldRay::proven_below_until(const BlobField& field, double tmax, double min_step) const {
  const double t = probed_at_, c = field.isovalue;
  // An upper bound of F over [t, s]: each source's largest value there,
  // at most its peak on the ray. It never falls as s grows.
  const auto bound = [&](double s) {
    double b = 0.0;
    for (std::size_t i = 0; i < spans.size(); ++i) {
      const RaySpan& span = spans[i];
      if (s < span.t0) break;  // not reached by s, nor any after it
      if (span.t1 < t) continue;  // left behind
      const double from = std::max(t, span.t0), to = std::min(s, span.t1);
      double u;
      if (span.t0 <= t) {
        // Known at t: convex, so above its tangent; past its closest
        // approach it only grows.
        u = du_dt_[i] < 0.0 ? u_[i] + du_dt_[i] * (to - t) : u_[i];
      } else {
        // Not yet entered: u ≥ 1 at the support's edge t0, and u changes
        // at most Lσ√a per unit (glyph_shape.h).
        const ShapeParams& shape = shape_params(field, span.source);
        const double rate = std::sqrt(span.a) * double(shape.bound_scale) * double(shape.lipschitz);
        u = 1.0 - rate * (to - span.t0);
      }
      // And u ≥ √g_e, the bounding ellipsoid's, smallest where the ray is
      // closest to its centre.
      const double g = std::max(std::max(u, 0.0) * std::max(u, 0.0), span.g(std::clamp(span.t_c, from, to)));
      b = blended(field.blend, b, kernel_value(field.kernel, g));
    }
    return b;
  };
  // Out from t by doubling steps, from the last proof's length, to the
  // first s the bound does not clear (a sum up to s costs only the spans
  // begun by s, so the short tries are cheap), then halving:
  // bound(lo) < C ≤ bound(hi); within a hundredth of the way is far enough.
  double lo = t, hi = tmax;
  for (double step = std::max(proof_step_, min_step);; step *= 2.0) {
    const double s = std::min(t + step, tmax);
    if (bound(s) >= c) {
      hi = s;
      break;
    }
    lo = s;
    if (s >= tmax) return tmax;
  }
  for (int i = 0; i < 40 && hi - lo > std::max(0.01 * (lo - t), min_step); ++i) {
    const double mid = 0.5 * (lo + hi);
    (bound(mid) < c ? lo : hi) = mid;
  }
  proof_step_ = lo - t;
  return lo;
}

double FieldRay::shape_trace(const BlobField& field, double tmin, double tmax, const TraceSettings& settings,
                             TraceStats& stats) {
  const double c = field.isovalue;
  // Past the last support F is 0: the search for a proof stays short of it.
  double last = tmin;
  for (const RaySpan& s : spans) last = std::max(last, s.t1);
  tmax = std::min(tmax, last);
  double t = tmin, f = shape_value_at(field, t, stats);
  if (f >= c) return t;
  for (int steps = 0;;) {
    const double reach = proven_below_until(field, tmax, settings.min_step);
    if (reach >= tmax) return -1.0;
    if (++steps > settings.max_steps) {
      ++stats.step_limit_hits;
      return -1.0;
    }
    const double next = std::min(std::max(reach, t + settings.min_step), tmax);
    const double f_next = shape_value_at(field, next, stats);
    if (f_next >= c) return refine(field, t, next, f, f_next, stats);
    t = next;
    f = f_next;
  }
}

}  // namespace hsb
