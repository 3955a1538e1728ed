#include "renderer/surface/support_sweep.h"

#include <algorithm>

namespace hsb {

void SupportSweep::begin(const std::vector<RaySpan>& spans, double tmin, double tmax) {
  spans_ = &spans;
  entry_scratch_.clear();
  for (std::size_t i = 0; i < spans.size(); ++i)
    if (spans[i].t0 < tmax) entry_scratch_.push_back({spans[i].t0, std::uint32_t(i)});
  entries_.assign(entry_scratch_, tmin);
  exits_.clear();
  heaped_ = 0;
  slot_.assign(spans.size(), -1);
  active_.clear();
  cursor_ = tmin;
}

void SupportSweep::settle_exits() {
  const std::size_t added = exits_.size() - heaped_;
  if (added > heaped_) {
    std::make_heap(exits_.begin(), exits_.end(), Later());
  } else {
    for (std::size_t k = heaped_ + 1; k <= exits_.size(); ++k)
      std::push_heap(exits_.begin(), exits_.begin() + std::ptrdiff_t(k), Later());
  }
  heaped_ = exits_.size();
}

std::uint32_t SupportSweep::pop_exit() {
  std::pop_heap(exits_.begin(), exits_.end(), Later());
  const std::uint32_t i = exits_.back().index;
  exits_.pop_back();
  heaped_ = exits_.size();
  return i;
}

void SupportSweep::add(std::uint32_t i) {
  slot_[i] = std::int32_t(active_.size());
  active_.push_back(i);
  exits_.push_back({(*spans_)[i].t1, i});
}

void SupportSweep::remove(std::uint32_t i) {
  const std::int32_t at = slot_[i];
  const std::uint32_t last = active_.back();
  active_[std::size_t(at)] = last;
  slot_[last] = at;
  active_.pop_back();
  slot_[i] = -1;
}

void SupportSweep::sort_active() {
  const std::vector<RaySpan>& spans = *spans_;
  std::sort(active_.begin(), active_.end(), [&](std::uint32_t x, std::uint32_t y) {
    return spans[x].t0 < spans[y].t0 || (spans[x].t0 == spans[y].t0 && spans[x].rank < spans[y].rank);
  });
  for (std::size_t k = 0; k < active_.size(); ++k) slot_[active_[k]] = std::int32_t(k);
}

}  // namespace hsb
