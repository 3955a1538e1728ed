#include "renderer/surface/event_queue.h"

namespace hsb {

void RayEventQueue::assign(std::vector<RayEvent>& events, double lo) {
  const std::size_t count = events.size();
  next_ = sorted_until_ = next_bin_ = 0;
  if (count <= kSortedAtOnce) {
    // A few: sorted at once, in place (the caller's vector and ours swap
    // buffers, so neither is copied nor reallocated).
    events_.swap(events);
    for (std::size_t i = 1; i < count; ++i) {
      const RayEvent e = events_[i];
      std::size_t j = i;
      for (; j > 0 && e < events_[j - 1]; --j) events_[j] = events_[j - 1];
      events_[j] = e;
    }
    sorted_until_ = count;
    bin_start_.assign({0u, std::uint32_t(count)});
    next_bin_ = 1;
    return;
  }
  double hi = lo;
  for (const RayEvent& e : events) hi = std::max(hi, e.t);
  // Counting sort into `count` bins of equal length over [lo, hi].
  const std::size_t bins = std::max<std::size_t>(1, count);
  const double per_t = hi > lo ? double(bins) / (hi - lo) : 0.0;
  const auto bin_of = [&](double t) { return std::min(bins - 1, std::size_t(std::max(0.0, (t - lo) * per_t))); };
  bin_start_.assign(bins + 1, 0);
  for (const RayEvent& e : events) ++bin_start_[bin_of(e.t) + 1];
  for (std::size_t b = 0; b < bins; ++b) bin_start_[b + 1] += bin_start_[b];
  bin_fill_.assign(bin_start_.begin(), bin_start_.end() - 1);
  events_.resize(count);
  for (const RayEvent& e : events) events_[bin_fill_[bin_of(e.t)]++] = e;
}

}  // namespace hsb
