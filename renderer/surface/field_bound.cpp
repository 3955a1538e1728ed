#include "renderer/surface/field_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/surface/ray_polynomial.h"

namespace hsb {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// Up to this many active sources the sum of their own values is the
// cheaper proof; and for the first few segments of a walk, which often ends
// there (a shadow ray is soon clear of the crowd it left).
constexpr std::size_t kFewSources = 8;
constexpr std::uint32_t kWarmUpSegments = 2;

// Rebuild once the rounding estimate exceeds this fraction of the level:
// below it a rebuild could not change the answer often enough to pay.
constexpr double kStaleFraction = 1e-3;

}  // namespace

void FieldUpperBound::reset(const KernelTraits& kernel, const std::vector<RaySpan>& spans,
                            const std::vector<double>& peaks, double tmin, bool ends_on_surface) {
  kernel_ = &kernel;
  ends_on_surface_ = ends_on_surface;
  degree_ = 2 * kernel.degree_in_g;
  engaged_ = false;
  segments_ = 0;
  peaks_ = &peaks;
  ahead_scratch_.clear();
  ahead_sum_ = 0.0;
  if (!ends_on_surface) {
    for (std::size_t i = 0; i < spans.size(); ++i) {
      const RaySpan& s = spans[i];
      const double t = peak_t(s);
      if (t > tmin) {
        ahead_scratch_.push_back({t, std::uint32_t(i)});
        ahead_sum_ += peaks[i];
      }
    }
  }
  ahead_total_ = ahead_sum_;
  ahead_updates_ = std::uint32_t(ahead_scratch_.size());
  ahead_.assign(ahead_scratch_, tmin);
}

bool FieldUpperBound::engage(double origin, const std::vector<RaySpan>& spans,
                             const std::vector<std::uint32_t>& active) {
  if (engaged_) return true;
  if (active.size() <= kFewSources || segments_ <= kWarmUpSegments) return false;
  rebuild(origin, spans, active);
  return true;
}

void FieldUpperBound::rebuild(double origin, const std::vector<RaySpan>& spans,
                              const std::vector<std::uint32_t>& active) {
  origin_ = origin;
  coefficients_.fill(0.0);
  magnitudes_.fill(0.0);
  updates_ = sources_ = 0;
  engaged_ = true;
  for (const std::uint32_t i : active) update(spans[i], 1.0);
}

void FieldUpperBound::update(const RaySpan& s, double sign) {
  add_kernel_along_ray(*kernel_, s.g(origin_), 2.0 * s.a * (origin_ - s.t_c), s.a, sign, coefficients_,
                       &magnitudes_);
  ++updates_;
  sources_ = sign > 0.0 ? sources_ + 1 : sources_ - 1;
  // An empty sum is exactly zero; the next crowd starts afresh.
  if (sources_ == 0) engaged_ = false;
}

RayPolynomial FieldUpperBound::bernstein_on(double start, double end, double& error) const {
  const double delta = start - origin_, h = end - start;
  RayPolynomial p = coefficients_;
  taylor_shift(p, degree_, delta);
  double scale = 1.0;
  for (int j = 0; j <= degree_; ++j) {
    p[std::size_t(j)] *= scale;
    scale *= h;
  }
  // Each coefficient is a sum of at most `updates_` terms no larger than
  // its magnitude; the shift, scaling and change of basis add a few
  // roundings of terms of the same size. Σ M_j (|δ| + h)^j bounds every
  // term of the polynomial on the segment, so this bounds the error of
  // every Bernstein coefficient, with a factor of two to spare.
  const double reach = std::fabs(delta) + h;
  double terms = 0.0, power = 1.0;
  for (int j = 0; j <= degree_; ++j) {
    terms += magnitudes_[std::size_t(j)] * power;
    power *= reach;
  }
  error = 2.0 * (double(updates_) + 4.0 * degree_ + 16.0) * kEpsilon * terms;
  return to_bernstein(p, degree_);
}

void FieldUpperBound::bound_on(double start, double end, double& largest, double& error) const {
  const RayPolynomial b = bernstein_on(start, end, error);
  largest = *std::max_element(b.begin(), b.begin() + degree_ + 1);
}

bool FieldUpperBound::bernstein_form(double start, double end, double tolerance, RayPolynomial& bernstein,
                                     int& degree) const {
  if (!engaged_ || !kernel_->exact) return false;
  double error;
  bernstein = bernstein_on(start, end, error);
  degree = degree_;
  return error <= tolerance;
}

bool FieldUpperBound::proves_below(double level, double start, double end, const std::vector<RaySpan>& spans,
                                   const std::vector<std::uint32_t>& active) {
  ++segments_;
  if (!engage(start, spans, active)) {
    double sum = 0.0;  // each source peaks where its g is smallest on the segment
    for (const std::uint32_t i : active) {
      const RaySpan& s = spans[i];
      sum += kernel_value(kernel_->kind, s.g(std::clamp(s.t_c, start, end)));
    }
    return sum < level;
  }
  double largest, error;
  bound_on(start, end, largest, error);
  if (largest + error < level) return true;
  if (error < kStaleFraction * level || updates_ <= active.size()) return false;
  // The accumulated rounding may be what stands in the way: rebuild from
  // the active sources alone, about this segment's start, and try again.
  rebuild(start, spans, active);
  bound_on(start, end, largest, error);
  return largest + error < level;
}

bool FieldUpperBound::proves_rest_below(double level, double start, const std::vector<RaySpan>& spans,
                                        const std::vector<std::uint32_t>& active) {
  if (ends_on_surface_) return false;
  for (RayEvent passed; ahead_.peek(passed) && passed.t <= start; ahead_.pop()) {
    ahead_sum_ -= (*peaks_)[passed.index];
    ++ahead_updates_;
  }
  // The running sum of positive values, less those passed: its rounding
  // is at most one ulp of the starting total per update.
  const double ahead = ahead_sum_ + double(ahead_updates_) * kEpsilon * ahead_total_;
  if (ahead >= level) return false;
  // `ahead` holds the peak of every source still approaching, active or
  // not yet entered. An active source past its closest approach only falls
  // from here on: its value now bounds the rest of its support. Counting
  // only those (not the whole running sum, which would count the
  // approaching ones twice) lets a ray leaving a crowd stop its walk as
  // soon as the sources it is moving away from have fallen far enough.
  double receding = 0.0;
  for (const std::uint32_t i : active) {
    const RaySpan& s = spans[i];
    if (s.t_c <= start) receding += kernel_value(kernel_->kind, s.g(start));
  }
  // A sum of positive values and their own roundings: a few ulps each.
  const double rounding = (double(active.size()) + 4.0) * kEpsilon * receding;
  return receding + rounding + ahead < level;
}

}  // namespace hsb
