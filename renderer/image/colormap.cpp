#include "renderer/image/colormap.h"

#include <algorithm>
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

double ColorScale::normalized(double value) const {
  if (!log) return (value - lo) / (hi - lo);
  if (!(value > 0.0)) return 0.0;
  return (std::log10(value) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
}

namespace {

// The q-quantile (q ∈ [0, 1]) of `values`, by nearest rank.
double quantile(std::vector<double> values, double q) {
  const std::size_t k = std::min(values.size() - 1, std::size_t(q * double(values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

}  // namespace

ColorScale auto_scale(const Colormap& map, const std::vector<double>& values, bool symmetric, bool log) {
  ColorScale scale{&map, 0.0, 1.0, log};
  if (log) {
    std::vector<double> positive;
    for (double v : values)
      if (v > 0.0 && std::isfinite(v)) positive.push_back(v);
    if (positive.empty()) {
      scale.lo = 1.0, scale.hi = 10.0;
      return scale;
    }
    scale.lo = quantile(positive, 0.02);
    scale.hi = quantile(positive, 0.98);
    if (!(scale.hi > scale.lo)) scale.lo /= 10.0, scale.hi *= 10.0;
    return scale;
  }
  if (values.empty()) return scale;
  if (symmetric) {
    std::vector<double> magnitudes(values.size());
    std::transform(values.begin(), values.end(), magnitudes.begin(), [](double v) { return std::fabs(v); });
    const double m = quantile(std::move(magnitudes), 0.98);
    scale.lo = -m;
    scale.hi = m;
  } else {
    scale.lo = quantile(values, 0.02);
    scale.hi = quantile(values, 0.98);
  }
  if (!(scale.hi > scale.lo)) {
    const double pad = std::max(1.0, std::fabs(scale.lo)) * 1e-6;
    scale.lo -= pad;
    scale.hi += pad;
  }
  return scale;
}

}  // namespace hsb
