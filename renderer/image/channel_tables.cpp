#include "renderer/image/channel_tables.h"

#include <cmath>

namespace OCIO = OCIO_NAMESPACE;

namespace hsb {
namespace {

// `processor` applied to the RGBA values (r, r, r, alpha) for each r of `at`.
std::vector<float> transformed(const OCIO::ConstCPUProcessorRcPtr& processor, const std::vector<double>& at,
                               float alpha) {
  std::vector<float> rgba;
  rgba.reserve(at.size() * 4);
  for (double r : at) rgba.insert(rgba.end(), {float(r), float(r), float(r), alpha});
  OCIO::PackedImageDesc image(rgba.data(), long(at.size()), 1, 4);
  processor->apply(image);
  return rgba;
}

}  // namespace

std::optional<ChannelTables> ChannelTables::of(const OCIO::ConstCPUProcessorRcPtr& processor) {
  if (processor->hasChannelCrosstalk()) return std::nullopt;
  std::vector<double> nodes(kIntervals + 1), middles(kIntervals);
  for (int i = 0; i <= kIntervals; ++i) nodes[std::size_t(i)] = double(i) / kIntervals;
  for (int i = 0; i < kIntervals; ++i) middles[std::size_t(i)] = (i + 0.5) / kIntervals;
  constexpr float kAlpha = 0.5f;
  const std::vector<float> at_nodes = transformed(processor, nodes, kAlpha);
  const std::vector<float> at_middles = transformed(processor, middles, kAlpha);

  ChannelTables tables;
  for (int c = 0; c < 3; ++c) {
    std::vector<float>& table = tables.table_[c];
    table.resize(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      table[i] = at_nodes[4 * i + std::size_t(c)];
      if (!std::isfinite(table[i]) || at_nodes[4 * i + 3] != kAlpha) return std::nullopt;
    }
    for (std::size_t i = 0; i < middles.size(); ++i) {
      const float interpolated = 0.5f * (table[i] + table[i + 1]);
      if (!(std::abs(interpolated - at_middles[4 * i + std::size_t(c)]) <= kTolerance)) return std::nullopt;
    }
  }
  return tables;
}

bool ChannelTables::apply(float* rgb) const {
  if (!(rgb[0] >= 0.0f && rgb[0] <= 1.0f && rgb[1] >= 0.0f && rgb[1] <= 1.0f && rgb[2] >= 0.0f && rgb[2] <= 1.0f))
    return false;
  for (int c = 0; c < 3; ++c) {
    const float at = rgb[c] * float(kIntervals);
    const int i = std::min(int(at), kIntervals - 1);
    const float t = at - float(i);
    const std::vector<float>& table = table_[c];
    rgb[c] = table[std::size_t(i)] + t * (table[std::size_t(i) + 1] - table[std::size_t(i)]);
  }
  return true;
}

}  // namespace hsb
