#pragma once
// Upper bounds of F along a ray, kept current as the walk (support_sweep.h)
// moves, so that proving F < C somewhere costs the same however many
// sources are active.
//
// The running sum: over the active sources, each one's kernel polynomial
// (kernel.h: K itself, or a polynomial above it) composed with its g(t),
// kept as one polynomial in t. A source's coefficients are added when its
// support opens and subtracted when it closes, as POV-Ray's blob does.
// Subtraction cancels, so the sum carries a rigorous estimate of its own
// rounding (every coefficient ever added or removed, in magnitude) and
// counts it against any proof; when the estimate has grown until it is what
// stands in the way, the polynomial is rebuilt from the active sources.
// Most rays cross a handful of supports; for them the sources' own peaks
// are cheaper than any polynomial, so the polynomial is only built once a
// segment holds more than a few sources, and dropped when the set empties.
//
// The peaks still ahead: a source past its closest approach only falls, so
// from t on F is at most the running sum at t plus the peak of every source
// not yet past its own. A ray leaving a dense crowd (a shadow ray from a
// blended cap) is soon past every peak that could lift F, long before it is
// past every support, and its walk can stop there.
//
// These bounds only ever skip work: where they cannot prove F < C the
// intersectors compute F from scratch.

#include <array>
#include <cstdint>
#include <vector>

#include "renderer/surface/event_queue.h"
#include "renderer/surface/kernel.h"
#include "renderer/surface/ray_polynomial.h"
#include "renderer/surface/ray_span.h"

namespace hsb {

class FieldUpperBound {
 public:
  // Starts a walk from `tmin` over `spans`; peaks[i] is span i's largest
  // value on its interval. A walk that ends where F ≥ C is known (a single
  // source's entry) cannot be proven below C to its end, and keeps no
  // peaks ahead for proves_rest_below().
  void reset(const KernelTraits& kernel, const std::vector<RaySpan>& spans, const std::vector<double>& peaks,
             double tmin, bool ends_on_surface);

  // A source joins or leaves the active set.
  void add(const RaySpan& s) {
    if (engaged_) update(s, 1.0);
  }
  void remove(const RaySpan& s) {
    if (engaged_) update(s, -1.0);
  }

  // True when F < level everywhere on [start, end], rounding included.
  // `active` are the segment's sources; they rebuild the polynomial when
  // its accumulated rounding is what prevents the proof.
  bool proves_below(double level, double start, double end, const std::vector<RaySpan>& spans,
                    const std::vector<std::uint32_t>& active);
  // The running sum on [start, end] in Bernstein form, when it is being
  // kept and its rounding is below `tolerance`: then it stands for F itself,
  // and the exact intersector needs no sum from scratch. False otherwise.
  bool bernstein_form(double start, double end, double tolerance, RayPolynomial& bernstein, int& degree) const;
  // True when F < level everywhere from `start` to the end of the walk
  // (never for a walk that ends on the surface).
  bool proves_rest_below(double level, double start, const std::vector<RaySpan>& spans,
                         const std::vector<std::uint32_t>& active);

 private:
  // Keeps the polynomial when the segment holds more than a few sources;
  // false when it is cheaper to sum the few sources' own values.
  bool engage(double origin, const std::vector<RaySpan>& spans, const std::vector<std::uint32_t>& active);
  // The polynomial of the active sources, in powers of (t − origin).
  void rebuild(double origin, const std::vector<RaySpan>& spans, const std::vector<std::uint32_t>& active);
  void update(const RaySpan& s, double sign);
  // The polynomial on [start, end] in Bernstein form, and the rounding
  // any of its coefficients may carry.
  RayPolynomial bernstein_on(double start, double end, double& error) const;
  // Its largest coefficient: an upper bound of its values there.
  void bound_on(double start, double end, double& largest, double& error) const;

  const KernelTraits* kernel_ = nullptr;
  int degree_ = 0;             // in t: twice the kernel's degree in g
  double origin_ = 0.0;        // coefficients are in powers of (t − origin)
  RayPolynomial coefficients_{};
  RayPolynomial magnitudes_{};  // Σ |coefficient| over every update since the last rebuild
  std::uint32_t updates_ = 0;
  std::uint32_t sources_ = 0;  // active: at zero the sum is exactly zero again
  bool engaged_ = false;       // the polynomial is being kept
  std::uint32_t segments_ = 0;  // tested so far in this walk

  const std::vector<double>* peaks_ = nullptr;
  std::vector<RayEvent> ahead_scratch_;
  RayEventQueue ahead_;        // each span's closest approach on its interval, not yet passed
  double ahead_sum_ = 0.0;     // the peak values there
  double ahead_total_ = 0.0;   // the sum at the start, for its rounding
  std::uint32_t ahead_updates_ = 0;
  bool ends_on_surface_ = false;
};

}  // namespace hsb
