#pragma once
// A display transform that treats each channel alone (sRGB's or a gamma's
// encoding: no channel crosstalk), applied through a table a channel. OCIO
// evaluates such a transform with a powf a value: 12 million of them for a
// 4-megapixel picture, 0.1 s of two cores' time, where interpolating in a
// table takes a few milliseconds.

#include <OpenColorIO/OpenColorIO.h>

#include <optional>
#include <vector>

namespace hsb {

class ChannelTables {
 public:
  // Tables of `processor` over [0, 1], or none where it mixes channels,
  // changes alpha, or where linear interpolation between the tables' nodes
  // strays more than kTolerance from it at any interval's midpoint (a
  // logarithmic or PQ encoding's steep foot): the caller then keeps OCIO.
  static std::optional<ChannelTables> of(const OCIO_NAMESPACE::ConstCPUProcessorRcPtr& processor);

  // The largest error allowed: a tenth of a 16-bit level.
  static constexpr float kTolerance = 0.1f / 65535.0f;

  // The transform of an RGB value whose channels are all within [0, 1],
  // in place; false (and `rgb` untouched) for one that is not (a
  // highlight beyond 1): that one is OCIO's.
  bool apply(float* rgb) const;

 private:
  static constexpr int kIntervals = 16384;
  std::vector<float> table_[3];  // kIntervals + 1 nodes a channel
};

}  // namespace hsb
