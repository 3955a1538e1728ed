#include "renderer/image/ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hsb {
namespace {

const char* const kMinus = "\u2212";

std::string superscript(int n) {
  static const char* const digits[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                       "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string out = n < 0 ? "\u207b" : "";
  const std::string text = std::to_string(std::abs(n));
  for (char c : text) out += digits[c - '0'];
  return out;
}

// `value` with `decimals` digits after the point, a true minus sign, and
// no "−0".
std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", std::max(0, decimals), value);
  std::string s = text;
  if (s[0] == '-') {
    const bool zero = s.find_first_not_of("-0.") == std::string::npos;
    s = zero ? s.substr(1) : kMinus + s.substr(1);
  }
  return s;
}

// 1, 2 or 5 × 10ⁿ: the round step nearest to giving `target` intervals.
double round_step(double span, int target) {
  const double raw = span / std::max(1, target);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double m = raw / magnitude;
  return magnitude * (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0);
}

}  // namespace

std::string power_of_ten(int exponent) { return "10" + superscript(exponent); }

std::string value_label(double value, int exponent) {
  const double v = value / std::pow(10.0, exponent);
  if (!std::isfinite(v)) return v > 0 ? "\u221e" : v < 0 ? std::string(kMinus) + "\u221e" : "?";
  const int digits = v == 0.0 ? 0 : int(std::floor(std::log10(std::fabs(v))));
  if (digits > 5 || digits < -3) {
    const int e = digits;
    return fixed(v / std::pow(10.0, e), 2) + "\u00d7" + power_of_ten(e);
  }
  return fixed(v, std::max(0, 2 - digits));
}

namespace {

// Plain digits between 10⁻³ and 10⁴; beyond, a shared factor of 10ᵉ (a
// multiple of three, as engineers write units).
int factor_exponent(double largest) {
  return largest >= 1e4 || largest < 1e-3 ? 3 * int(std::floor(std::log10(largest) / 3.0)) : 0;
}

TickSet ticks_in_unit(double lo, double hi, int target, int exponent);

}  // namespace

TickSet linear_ticks(double lo, double hi, int target) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {};
  return ticks_in_unit(lo, hi, target, factor_exponent(std::max(std::fabs(lo), std::fabs(hi))));
}

TickSet two_sided_ticks(double lo, double hi, int target) {
  if (!(lo < 0.0 && hi > 0.0) || !std::isfinite(lo) || !std::isfinite(hi)) return linear_ticks(lo, hi, target);
  const int exponent = factor_exponent(std::max(-lo, hi)), half = std::max(2, (target + 1) / 2);
  TickSet set = ticks_in_unit(lo, 0.0, half, exponent);
  for (Tick& t : ticks_in_unit(0.0, hi, half, exponent).ticks)
    if (t.value > 0.0) set.ticks.push_back(std::move(t));
  return set;
}

namespace {

TickSet ticks_in_unit(double lo, double hi, int target, int exponent) {
  TickSet set;
  const double largest = std::max(std::fabs(lo), std::fabs(hi));
  const double unit = std::pow(10.0, exponent);
  if (exponent != 0) set.factor = "\u00d7" + power_of_ten(exponent);
  set.exponent = exponent;
  // A range too narrow for round steps between its values to be told
  // apart (constant data up to round-off): one tick, in the middle, with
  // six significant digits.
  if (hi - lo <= 1e-9 * largest) {
    const double mid = lo + 0.5 * (hi - lo);
    const int digits = mid == 0.0 ? 0 : int(std::floor(std::log10(std::fabs(mid) / unit)));
    set.ticks.push_back({mid, fixed(mid / unit, std::max(0, 5 - digits))});
    return set;
  }
  // A range across the whole of double's overflows its width: then the
  // step for half of it, doubled.
  const double span = hi - lo;
  double step = std::isfinite(span) ? round_step(span, target) : 2.0 * round_step(0.5 * hi - 0.5 * lo, target);
  // Fewer than two ticks inside is no scale: halve the step until there are.
  for (int tries = 0; tries < 4 && std::floor(hi / step) - std::ceil(lo / step) < 1.0; ++tries)
    step = round_step(step, 2);
  const int decimals = std::max(0, -int(std::floor(std::log10(step / unit) + 1e-9)));
  // Counted, not stepped: k += 1 would stand still where k is beyond 2⁵³.
  const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
  const int count = int(std::clamp(last - first + 1.0, 0.0, 4.0 * std::max(1, target) + 2.0));
  for (int i = 0; i < count; ++i) {
    const double v = (first + i) * step;
    set.ticks.push_back({v, fixed(v / unit, decimals)});
  }
  return set;
}

}  // namespace

TickSet log_ticks(double lo, double hi) {
  TickSet set;
  if (!(lo > 0.0) || !(hi > lo)) return set;
  if (!std::isfinite(hi)) return set;
  const int first = int(std::ceil(std::log10(lo) - 1e-9)), last = int(std::floor(std::log10(hi) + 1e-9));
  const bool fine = std::log10(hi) - std::log10(lo) < 2.0;
  // Over many decades, every 2nd, 5th, 10th … power, so that at most
  // eight labels share the bar.
  int stride = 1;
  for (const int s : {1, 2, 5, 10, 20, 50, 100, 200, 500}) {
    stride = s;
    if ((last - first) / s <= 7) break;
  }
  for (int e = first - 1; e <= last; ++e) {
    if (e % stride != 0) continue;
    for (const double m : {1.0, 2.0, 5.0}) {
      if (m != 1.0 && !fine) continue;
      const double v = m * std::pow(10.0, e);
      if (v < lo * (1.0 - 1e-12) || v > hi * (1.0 + 1e-12)) continue;
      const bool plain = e >= -3 && e <= 3;
      set.ticks.push_back({v, plain ? fixed(v, std::max(0, -e)) : (m == 1.0 ? "" : fixed(m, 0) + "\u00d7") + power_of_ten(e)});
    }
  }
  return set;
}

}  // namespace hsb
