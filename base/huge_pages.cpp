#include "base/huge_pages.h"

#include <sys/mman.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace hsb {

namespace {
constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;
}  // namespace

void advise_huge_pages(void* data, std::size_t bytes) {
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHugePage - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

void first_touch_in_parallel(void* data, std::size_t bytes) {
  // Pieces between huge-page boundaries: two threads never share the
  // clearing of one page. A few megabytes are not worth the threads.
  if (bytes < 4 * kHugePage) {
    std::memset(data, 0, bytes);
    return;
  }
  const auto begin = reinterpret_cast<std::uintptr_t>(data), end = begin + bytes;
  const std::uintptr_t first = begin & ~(kHugePage - 1);
  tbb::parallel_for(std::size_t{0}, std::size_t((end - first + kHugePage - 1) / kHugePage), [&](std::size_t k) {
    const std::uintptr_t from = std::max(begin, first + k * kHugePage), to = std::min(end, first + (k + 1) * kHugePage);
    std::memset(reinterpret_cast<void*>(from), 0, to - from);
  });
}

}  // namespace hsb
