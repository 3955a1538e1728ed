#include "renderer/surface/field_ray.h"

#include "renderer/surface/illinois.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsb {

double FieldRay::value_at(const BlobField& field, double t, TraceStats& stats) const {
  ++stats.field_evaluations;
  stats.kernel_evaluations += active_.size();
  double f = 0.0;
  if (field.blend == Blend::sum) {
    for (std::uint32_t i : active_) f += kernel_value(field.kernel, spans[i].g(t));
  } else {
    for (std::uint32_t i : active_) f = std::max(f, kernel_value(field.kernel, spans[i].g(t)));
  }
  return f;
}

// An upper bound on dF/dt from t to the end of the current segment. Only a
// source the ray is still approaching (t < t_c) can raise F, and on its
// support |d K(u(t))/dt| ≤ √a · max|dK/du| because u = √g changes at rate at
// most √a. Past t_c a source only falls, whichever segment we are in, so
// dropping it keeps the bound valid for the rest of the ray: it is one-sided,
// which is all that stepping towards F = C from below needs.
double FieldRay::slope_bound_at(const BlobField& field, double t) const {
  double rate = 0.0;
  for (std::uint32_t i : active_) {
    const RaySpan& s = spans[i];
    if (t >= s.t_c) continue;
    rate = field.blend == Blend::sum ? rate + std::sqrt(s.a) : std::max(rate, std::sqrt(s.a));
  }
  return rate * kernel_max_du_slope(field.kernel);
}

// The crossing inside a bracket F(lo) < C ≤ F(hi), to double precision.
double FieldRay::refine(const BlobField& field, double lo, double hi, double f_lo, double f_hi,
                        TraceStats& stats) const {
  const double c = field.isovalue;
  const double tolerance = 1e-14 * (std::fabs(lo) + std::fabs(hi)) + 1e-300;
  return illinois([&](double t) { return value_at(field, t, stats) - c; }, lo, hi, f_lo - c, f_hi - c,
                  tolerance, 0.0, 100);
}

double FieldRay::first_crossing(const BlobField& field, double tmin, double tmax,
                                const TraceSettings& settings, TraceStats& stats) {
  return settings.intersector == Intersector::exact ? exact_crossing(field, tmin, tmax, stats)
                                                    : sphere_trace(field, tmin, tmax, settings, stats);
}

void FieldRay::begin_segments(double tmin, TraceStats& stats) {
  stats.spans += spans.size();
  std::sort(spans.begin(), spans.end(), [](const RaySpan& x, const RaySpan& y) { return x.t0 < y.t0; });
  active_.clear();
  next_ = 0;
  cursor_ = tmin;
}

bool FieldRay::next_segment(double tmax, double& start, double& end) {
  const std::size_t n = spans.size();
  double t = cursor_;
  for (;;) {
    // Sources whose support has ended contribute K(1) = 0 from here on.
    active_.erase(std::remove_if(active_.begin(), active_.end(),
                                 [&](std::uint32_t i) { return spans[i].t1 <= t; }),
                  active_.end());
    if (active_.empty()) {
      if (next_ == n) return false;
      t = std::max(t, spans[next_].t0);  // F is zero in the gap: skip it
    }
    while (next_ < n && spans[next_].t0 <= t) {
      if (spans[next_].t1 > t) active_.push_back(static_cast<std::uint32_t>(next_));
      ++next_;
    }
    if (t >= tmax) return false;
    if (!active_.empty()) break;
  }
  end = tmax;
  if (next_ < n) end = std::min(end, spans[next_].t0);
  for (std::uint32_t i : active_) end = std::min(end, spans[i].t1);
  start = t;
  cursor_ = end;
  return true;
}

double FieldRay::sphere_trace(const BlobField& field, double tmin, double tmax,
                              const TraceSettings& settings, TraceStats& stats) {
  begin_segments(tmin, stats);
  const double c = field.isovalue;
  int steps = 0;
  double start, end;
  while (next_segment(tmax, start, end)) {
    double t = start;
    double f = value_at(field, t, stats);
    // Each segment begins where the previous one was found outside (or F is
    // zero before it), so this is the ray starting inside the surface, or a
    // crossing exactly on a segment boundary.
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
      if (f_next >= c) return refine(field, t, t_next, f, f_next, stats);
      t = t_next;
      f = f_next;
    }
  }
  return -1.0;
}

SurfaceSample FieldRay::surface_at(const BlobField& field, const Vec3& origin,
                                       const Vec3& direction, double t) const {
  const Vec3 x = origin + t * direction;
  Vec3 gradient = Vec3::Zero();
  double weight = 0.0, best = -1.0;
  Vec3 color = Vec3::Zero();
  for (const RaySpan& span : spans) {
    const BlobSource& s = field.sources[span.source];
    // q = W(x − c), g = |q|² and ∇g = 2 Wᵀ q.
    const Mat3 w = shape_matrix(s);
    const Vec3 q = scaled_offset(s, w, x);
    const double g = q.squaredNorm();
    const double k = kernel_value(field.kernel, g);
    if (k <= 0.0) continue;
    const Vec3 grad_g = 2.0 * (w.transpose() * q);
    const Vec3 source_color(s.color[0], s.color[1], s.color[2]);
    if (field.blend == Blend::sum) {
      gradient += kernel_slope(field.kernel, g) * grad_g;
      color += k * source_color;
      weight += k;
    } else if (k > best) {
      // max blend: the surface is the union, so the winning source alone
      // defines both normal and colour.
      best = k;
      gradient = kernel_slope(field.kernel, g) * grad_g;
      color = source_color;
      weight = 1.0;
    }
  }
  SurfaceSample sample;
  const double len = gradient.norm();
  // dK/dg < 0, so ∇F points inwards; the outward normal is −∇F/|∇F|.
  if (len > 0.0) sample.normal = -gradient / len;
  if (weight > 0.0) color /= weight;
  sample.color = {float(color[0]), float(color[1]), float(color[2])};
  return sample;
}

}  // namespace hsb
