#pragma once
// Buffers of tens of megabytes (the film's planes, a volume's tensors) on
// the kernel's transparent huge pages. Written for the first time 4 KB at
// a time, such a buffer takes a page fault a page: on Teem's helix glyph
// field at 2000², 87,000 faults, a fifth of the whole run's time on two
// cores. Marked before its first write, it is mapped 2 MB at a time.

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <vector>

namespace hsb {

// Asks the kernel to back the whole 2 MB pages inside [data, data + bytes)
// with huge pages (madvise MADV_HUGEPAGE). A hint: where the kernel has
// none to give, or huge pages are off, the memory stays as it was.
void advise_huge_pages(void* data, std::size_t bytes);

// Writes zeros over [data, data + bytes), memory not yet holding objects,
// a share on every core. A page's first write is its page fault, and the
// kernel clears the page there, in the writing thread: written by one
// thread, the 120 MB of Teem's helix at 136³ as double tensors took that
// thread a quarter of a second on a virtual machine whose host reclaims
// the guest's idle memory (the other core idle), half that on two.
void first_touch_in_parallel(void* data, std::size_t bytes);

// Room in `v` for `capacity` values, advised for huge pages before any
// is written (what `v` held is kept). Below 2 MB, an ordinary reserve.
template <class T>
void reserve_on_huge_pages(std::vector<T>& v, std::size_t capacity) {
  if (v.capacity() >= capacity) return;
  std::vector<T> room;
  room.reserve(capacity);
  advise_huge_pages(room.data(), capacity * sizeof(T));
  room.insert(room.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(room);
}

// `v` holding `n` copies of `value`, in room for `capacity` values (at
// least n) on huge pages, its new pages first written on every core.
template <class T>
void assign_on_huge_pages(std::vector<T>& v, std::size_t n, const T& value, std::size_t capacity = 0) {
  if (v.capacity() < std::max(capacity, n)) {
    std::vector<T>().swap(v);  // touched already: of no use
    reserve_on_huge_pages(v, std::max(capacity, n));
    first_touch_in_parallel(v.data(), n * sizeof(T));
  }
  v.assign(n, value);
}

}  // namespace hsb
