#pragma once
// The Illinois method (modified regula falsi): the root of f in a bracket
// f(lo) < 0 ≤ f(hi). Superlinear like the secant method, yet it never leaves
// the bracket, so a root found by a bound or by subdivision is refined
// without risk of jumping to another one.

namespace hsb {

// Returns the bracket's upper end (where f ≥ 0) once hi − lo ≤ tolerance,
// f(hi) ≤ f_tolerance, or max_iterations have been spent.
template <class F>
double illinois(F&& f, double lo, double hi, double f_lo, double f_hi, double tolerance,
                double f_tolerance, int max_iterations) {
  int side = 0;
  for (int i = 0; i < max_iterations && hi - lo > tolerance && f_hi > f_tolerance; ++i) {
    const double t = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    const double v = f(t);
    if (v >= 0.0) {
      hi = t;
      f_hi = v;
      if (side == 1) f_lo *= 0.5;  // the same end twice: halve the other's weight
      side = 1;
    } else {
      lo = t;
      f_lo = v;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    }
  }
  return hi;
}

}  // namespace hsb
