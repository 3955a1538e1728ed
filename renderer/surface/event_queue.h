#pragma once
// Events along a ray (a support's entry, a source's closest approach),
// taken in order of t. They are binned by t into as many equal stretches as
// there are events, and each bin is sorted only when it is reached: about
// O(k) for k events spread along the ray, O(k log k) at worst, and a walk
// that stops early pays only for the bins it reached. A few events (most
// rays cross a dozen or two supports) are sorted at once instead: binning
// them costs more than an insertion sort.

#include <emmintrin.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "base/bit_cast.h"

namespace hsb {

struct RayEvent {
  double t;
  std::uint32_t index;

  RayEvent() = default;
  // Stored as one 16-byte write. Written field by field (8 bytes, then 4),
  // an event was read back whole by the sort and the heap that take it a
  // moment later, and a 16-byte load of two smaller stores waits for them
  // to retire (a store-forwarding stall): three quarters of
  // SupportSweep::begin's samples sat on that one load.
  RayEvent(double at, std::uint32_t i) {
    const __m128i packed = _mm_set_epi64x(std::int64_t(i), bit_cast<std::int64_t>(at));
    std::memcpy(static_cast<void*>(this), &packed, sizeof packed);
  }

  // Ties go by index, so the order never depends on how events arrived.
  bool operator<(const RayEvent& o) const { return t < o.t || (t == o.t && index < o.index); }
};
static_assert(sizeof(RayEvent) == 16, "RayEvent is written as one 16-byte store");

class RayEventQueue {
 public:
  // Takes the events (any order); all must lie at or after `lo`. Leaves
  // `events` with unspecified contents (its buffer may be swapped in).
  void assign(std::vector<RayEvent>& events, double lo);

  // The next event, false when none is left.
  bool peek(RayEvent& next) {
    while (next_ == sorted_until_) {
      if (next_bin_ + 1 >= bin_start_.size()) return false;
      const std::size_t from = bin_start_[next_bin_], to = bin_start_[next_bin_ + 1];
      ++next_bin_;
      std::sort(events_.begin() + std::ptrdiff_t(from), events_.begin() + std::ptrdiff_t(to));
      sorted_until_ = to;
    }
    next = events_[next_];
    return true;
  }
  void pop() { ++next_; }

 private:
  std::vector<RayEvent> events_;          // grouped by bin, each bin sorted once reached
  std::vector<std::uint32_t> bin_start_;  // bin b holds events_[bin_start_[b], bin_start_[b + 1])
  std::vector<std::uint32_t> bin_fill_;   // where each bin is being filled (assign() only)
  std::size_t next_ = 0, sorted_until_ = 0, next_bin_ = 0;
  static constexpr std::size_t kSortedAtOnce = 40;  // up to this many, one sorted bin
};

}  // namespace hsb
