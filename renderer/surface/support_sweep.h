#pragma once
// The walk along a ray over its sources' support intervals. Between
// consecutive support endpoints the set of active sources is fixed, so the
// field there is one smooth function (one polynomial for the polynomial
// kernels): these stretches are the segments both intersectors work on.
//
// Entries come in t0 order from a lazily sorted queue (event_queue.h),
// exits off a heap of the active sources in t1 order, and a source joins or
// leaves the active set in O(1). Walking a ray through k supports costs
// O(k log k) at worst, about O(k) when the entries are spread out, and a
// walk that stops early (at a crossing, or at a bound on it) pays little
// for the entries it never reached. The caller hears of each entry and exit,
// which is how the running upper bound of F (field_bound.h) stays current
// without re-summing the active sources.

#include <cstdint>
#include <vector>

#include "renderer/surface/event_queue.h"
#include "renderer/surface/ray_span.h"

namespace hsb {

class SupportSweep {
 public:
  // Starts the walk at `tmin`; spans entered at or after `tmax` are never
  // visited. `spans` must stay untouched during the walk.
  void begin(const std::vector<RaySpan>& spans, double tmin, double tmax);

  // Advances to the next segment [start, end] holding at least one active
  // source; it ends at the next entry or exit or at tmax. Calls
  // entered(i) and left(i) with span indices as sources join and leave the
  // active set (left() also when the set empties over a gap). Returns false
  // when nothing is left before tmax.
  template <class Entered, class Left>
  bool next(double tmax, double& start, double& end, Entered&& entered, Left&& left);

  // The active spans' indices; in no particular order until sort_active().
  const std::vector<std::uint32_t>& active() const { return active_; }
  // Puts the active set in entry order (ties by spatial rank), so sums over
  // it depend neither on the order of the walk's updates nor on the order
  // the spans were collected in.
  void sort_active();

 private:
  void add(std::uint32_t i);
  void remove(std::uint32_t i);

  // The exits heap: a min-heap on t1 (ties by span index).
  struct Later {
    bool operator()(const RayEvent& x, const RayEvent& y) const { return y < x; }
  };
  std::uint32_t pop_exit();
  // Restores the exits heap after a run of entries: one heapify when many
  // sources entered at once (a ray starting inside a crowd), else one push
  // each.
  void settle_exits();

  const std::vector<RaySpan>* spans_ = nullptr;
  std::vector<RayEvent> entry_scratch_;
  RayEventQueue entries_;          // the spans the walk may reach, by t0
  std::vector<RayEvent> exits_;    // the active spans, a min-heap on t1
  std::size_t heaped_ = 0;         // exits_[0, heaped_) is the heap; the rest just entered
  std::vector<std::uint32_t> active_;
  std::vector<std::int32_t> slot_;     // position in active_, or −1
  double cursor_ = 0.0;
};

template <class Entered, class Left>
bool SupportSweep::next(double tmax, double& start, double& end, Entered&& entered, Left&& left) {
  const std::vector<RaySpan>& spans = *spans_;
  double t = cursor_;
  RayEvent entry;
  for (;;) {
    // Sources whose support has ended by t contribute K(1) = 0 from there on.
    while (!exits_.empty() && exits_.front().t <= t) {
      const std::uint32_t i = pop_exit();
      remove(i);
      left(i);
    }
    if (active_.empty()) {
      if (!entries_.peek(entry)) return false;
      if (entry.t > t) t = entry.t;  // F is zero in the gap: skip it
    }
    while (entries_.peek(entry) && entry.t <= t) {
      entries_.pop();
      // A span that ends before the walk reaches it is never entered.
      if (spans[entry.index].t1 > t) {
        add(entry.index);
        entered(entry.index);
      }
    }
    settle_exits();
    if (t >= tmax) return false;
    if (!active_.empty()) break;
  }
  end = tmax;
  if (entries_.peek(entry) && entry.t < end) end = entry.t;
  if (exits_.front().t < end) end = exits_.front().t;
  start = t;
  cursor_ = end;
  return true;
}

}  // namespace hsb
