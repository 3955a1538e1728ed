#pragma once
// The reference the intersectors are held to: the first t in [0, t_end]
// where f(t) ≥ level, found by sampling f at n + 1 evenly spaced points and
// bisecting the first bracket; 0 when f starts at or above the level, −1
// when no sample reaches it. A crossing narrower than t_end/n can fall
// between samples: the tests allow for that.

namespace hsb {

template <class F>
double sampled_crossing(F&& f, double level, double t_end, int n) {
  double previous = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double t = t_end * k / n;
    if (f(t) >= level) {
      if (k == 0) return 0.0;
      double lo = previous, hi = t;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) >= level ? hi : lo) = mid;
      }
      return hi;
    }
    previous = t;
  }
  return -1.0;
}

}  // namespace hsb
