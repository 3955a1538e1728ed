#include "renderer/surface/spatial_rank.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hsb {
namespace {

// The low 21 bits of x, spread to every third bit.
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

}  // namespace

std::vector<std::uint32_t> spatial_ranks(const BlobField& field, const Box3& bounds) {
  const std::size_t n = field.sources.size();
  constexpr double cells = double((1u << 21) - 1);
  const Vec3 size = bounds.size();
  std::vector<std::uint64_t> code(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t c = 0;
    for (int k = 0; k < 3; ++k) {
      const double u = size[k] > 0.0 ? (field.sources[i].centre[std::size_t(k)] - bounds.lo[k]) / size[k] : 0.0;
      c |= spread_bits(std::uint64_t(std::clamp(u, 0.0, 1.0) * cells)) << k;
    }
    code[i] = c;
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return code[a] < code[b] || (code[a] == code[b] && a < b); });
  std::vector<std::uint32_t> rank(n);
  for (std::size_t r = 0; r < n; ++r) rank[order[r]] = std::uint32_t(r);
  return rank;
}

}  // namespace hsb
