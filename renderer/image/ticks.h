#pragma once
// Tick marks for a colour bar: round values (1, 2 or 5 × 10ⁿ apart on a
// linear scale, powers of ten on a log one) and tidy labels, as a reader of
// a journal expects: "−200", "0", "1.5", never "-1.05e+03". Values too
// large or too small for plain digits share one factor, printed once
// ("×10⁶") instead of on every label.

#include <string>
#include <vector>

namespace hsb {

struct Tick {
  double value;
  std::string label;  // UTF-8: a true minus sign, superscript exponents
};

struct TickSet {
  std::vector<Tick> ticks;
  std::string factor;  // "" or "×10⁶": what every label is to be multiplied by
  int exponent = 0;    // the factor's: 10^exponent
};

// `value` in the ticks' unit (divided by 10^exponent) with three
// significant digits: a clipped extreme printed beside the bar.
std::string value_label(double value, int exponent);

// About `target` ticks (at least 2 where the range allows) inside [lo, hi].
TickSet linear_ticks(double lo, double hi, int target = 5);
// A range centred on zero with sides of different sizes (lo < 0 < hi; a
// colour bar's halves, ColorScale::centred_on_zero): each half's own
// round ticks, about target/2 of them, zero once, one factor for all.
TickSet two_sided_ticks(double lo, double hi, int target = 5);
// Powers of ten inside [lo, hi] (lo > 0), with 2 and 5 between them when
// the range spans less than two decades.
TickSet log_ticks(double lo, double hi);

// "10⁻³", "10⁶": ten to an integer power, in superscript digits.
std::string power_of_ten(int exponent);

}  // namespace hsb
