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
// least n) on huge pages.
template <class T>
void assign_on_huge_pages(std::vector<T>& v, std::size_t n, const T& value, std::size_t capacity = 0) {
  if (v.capacity() < std::max(capacity, n)) std::vector<T>().swap(v);  // touched already: of no use
  reserve_on_huge_pages(v, std::max(capacity, n));
  v.assign(n, value);
}

}  // namespace hsb
