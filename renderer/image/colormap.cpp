#include "renderer/image/colormap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "renderer/image/colormap_tables.h"

namespace hsb {
namespace {

// Every published table, and each reversed as "<name>_r".
std::vector<Colormap> make_colormaps() {
  std::vector<Colormap> maps;
  for (const ColormapTable& t : colormap_tables()) {
    Colormap map{t.name, {}, t.diverging};
    for (const auto& c : t.colors) map.table.push_back({c[0], c[1], c[2]});
    Colormap reversed{map.name + "_r", {map.table.rbegin(), map.table.rend()}, t.diverging};
    maps.push_back(std::move(map));
    maps.push_back(std::move(reversed));
  }
  return maps;
}

const std::vector<Colormap>& colormaps() {
  static const std::vector<Colormap> maps = make_colormaps();
  return maps;
}

}  // namespace

Rgb Colormap::at(double u) const {
  if (!(u >= 0.0)) u = 0.0;  // also catches NaN
  u = std::min(u, 1.0);
  const double x = u * double(table.size() - 1);
  const std::size_t i = std::min(std::size_t(x), table.size() - 2);
  const float f = float(x - double(i));
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = table[i][c] + f * (table[i + 1][c] - table[i][c]);
  return out;
}

const std::vector<std::string>& colormap_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const Colormap& m : colormaps()) out.push_back(m.name);
    return out;
  }();
  return names;
}

const Colormap& colormap_named(const std::string& name) {
  for (const Colormap& m : colormaps())
    if (m.name == name) return m;
  throw std::invalid_argument("unknown colormap \"" + name + "\"");
}

bool ColorScale::centred_on_zero() const { return map && map->diverging && !log && lo < 0.0 && hi > 0.0; }

double ColorScale::normalized(double value) const {
  // (A symmetric range is already centred: the one formula, to the bit.)
  if (two_sided()) return value < 0.0 ? 0.5 - 0.5 * value / lo : 0.5 + 0.5 * value / hi;
  if (!log) return (value - lo) / (hi - lo);
  if (!(value > 0.0)) return 0.0;
  return (std::log10(value) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
}

namespace {

// How far past the bulk of the values the automatic range reaches, in
// units of the bulk's extent (colormap.h).
constexpr double kFence = 3.0;

// The q-quantile (q ∈ [0, 1]) of `values`, by nearest rank.
double quantile(std::vector<double> values, double q) {
  const std::size_t k = std::min(values.size() - 1, std::size_t(q * double(values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

}  // namespace

namespace {

// The fenced range of the rule in colormap.h, over `v` (not empty).
std::array<double, 2> fenced(const std::vector<double>& v) {
  const double q02 = quantile(v, 0.02), q98 = quantile(v, 0.98);
  const double bulk = std::max({std::fabs(q02), std::fabs(q98), q98 - q02});
  const auto [lowest, highest] = std::minmax_element(v.begin(), v.end());
  return {std::max(*lowest, q02 - kFence * bulk), std::min(*highest, q98 + kFence * bulk)};
}

void widen_if_degenerate(ColorScale& scale) {
  if (scale.hi > scale.lo) return;
  const double pad = std::max(1.0, std::fabs(scale.lo)) * 1e-6;
  scale.lo -= pad;
  scale.hi += pad;
}

}  // namespace

void record_extremes(ColorScale& scale, const std::vector<double>& values) {
  double lo = INFINITY, hi = -INFINITY;
  for (double v : values)
    if (std::isfinite(v) && (!scale.log || v > 0.0)) lo = std::min(lo, v), hi = std::max(hi, v);
  scale.data_lo = std::isfinite(lo) ? lo : std::numeric_limits<double>::quiet_NaN();
  scale.data_hi = std::isfinite(hi) ? hi : std::numeric_limits<double>::quiet_NaN();
}

const Colormap& colormap_for(const std::optional<std::string>& name, const std::vector<double>& values, bool log) {
  return colormap_named(name.value_or(!log && both_signs(values) ? "coolwarm" : "viridis"));
}

bool both_signs(const std::vector<double>& values) {
  double lo = 0.0, hi = 0.0;
  for (double v : values)
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  const double largest = std::max(-lo, hi);
  return largest > 0.0 && -lo > 0.01 * largest && hi > 0.01 * largest;
}

ColorScale auto_scale(const Colormap& map, const std::vector<double>& values, bool symmetric, bool log) {
  ColorScale scale{&map, 0.0, 1.0, log};
  std::vector<double> finite;
  for (double v : values)
    if (std::isfinite(v) && (!log || v > 0.0)) finite.push_back(log ? std::log10(v) : v);
  if (log) {
    if (finite.empty()) {
      scale.lo = 1.0, scale.hi = 10.0;
      return scale;
    }
    const std::array<double, 2> range = fenced(finite);
    scale.lo = std::pow(10.0, range[0]);
    scale.hi = std::pow(10.0, range[1]);
    if (!(scale.hi > scale.lo)) scale.lo /= 10.0, scale.hi *= 10.0;
    record_extremes(scale, values);
    return scale;
  }
  if (finite.empty()) return scale;
  if (symmetric) {
    // Each side's fence, and both sides' together.
    std::vector<double> below, above;
    for (double& v : finite) {
      if (v < 0.0) below.push_back(-v);
      else if (v > 0.0) above.push_back(v);
      v = std::fabs(v);
    }
    const double m = fenced(finite)[1];
    scale.lo = -m;
    scale.hi = m;
    if (!below.empty() && !above.empty() && map.diverging) {
      const double m_below = fenced(below)[1], m_above = fenced(above)[1];
      if (std::max(m_below, m_above) > kSidesApart * std::min(m_below, m_above)) scale.lo = -m_below, scale.hi = m_above;
    }
  } else {
    const std::array<double, 2> range = fenced(finite);
    scale.lo = range[0];
    scale.hi = range[1];
  }
  widen_if_degenerate(scale);
  record_extremes(scale, values);
  return scale;
}

}  // namespace hsb
