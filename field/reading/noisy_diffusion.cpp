#include "field/reading/noisy_diffusion.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <limits>
#include <sstream>

namespace hsb {

bool positive_definite(const Sym3& t) {
  const double m2 = t.xx * t.yy - t.xy * t.xy;
  const double det = t.xx * (t.yy * t.zz - t.yz * t.yz) - t.xy * (t.xy * t.zz - t.yz * t.xz) +
                     t.xz * (t.xy * t.yz - t.yy * t.xz);
  return t.xx > 0.0 && m2 > 0.0 && det > 0.0;
}

NoiseLeftOut leave_out_noise(std::vector<Sym3>& tensors, const std::array<int, 3>* dims) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const Sym3 no_data{nan, nan, nan, nan, nan, nan};
  std::atomic<std::size_t> with_data{0}, indefinite{0};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tensors.size(), 1 << 14),
                    [&](const tbb::blocked_range<std::size_t>& band) {
                      std::size_t held = 0, left = 0;
                      for (std::size_t i = band.begin(); i < band.end(); ++i) {
                        Sym3& t = tensors[i];
                        if (!t.holds_data()) continue;
                        ++held;
                        if (!positive_definite(t)) t = no_data, ++left;
                      }
                      with_data += held;
                      indefinite += left;
                    });
  NoiseLeftOut out{with_data, indefinite, 0};
  if (!dims || out.indefinite == 0) return out;
  // Decided from the data as the first pass left it, then applied, so
  // that the order nodes are visited in changes nothing.
  const int nx = (*dims)[0], ny = (*dims)[1], nz = (*dims)[2];
  const auto index = [&](int i, int j, int k) { return std::size_t(i) + std::size_t(nx) * (std::size_t(j) + std::size_t(ny) * std::size_t(k)); };
  std::vector<std::uint8_t> alone(tensors.size(), 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, nz), [&](const tbb::blocked_range<int>& slabs) {
    for (int k = slabs.begin(); k < slabs.end(); ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          if (!tensors[index(i, j, k)].holds_data()) continue;
          int neighbours = 0;
          for (int dk = -1; dk <= 1; ++dk)
            for (int dj = -1; dj <= 1; ++dj)
              for (int di = -1; di <= 1; ++di) {
                const int a = i + di, b = j + dj, c = k + dk;
                if ((di | dj | dk) == 0 || a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz) continue;
                neighbours += tensors[index(a, b, c)].holds_data();
              }
          alone[index(i, j, k)] = neighbours < kSpeckleNeighbours;
        }
  });
  for (std::size_t i = 0; i < tensors.size(); ++i)
    if (alone[i]) tensors[i] = no_data, ++out.speckle;
  return out;
}

std::string noise_warning(const std::string& path, const NoiseLeftOut& out) {
  if (out.indefinite + out.speckle == 0) return "";
  const auto percent = [&](std::size_t n) {
    std::ostringstream p;
    p.precision(n * 1000 >= out.with_data ? 3 : 2);
    p << 100.0 * double(n) / double(std::max<std::size_t>(out.with_data, 1)) << " %";
    return p.str();
  };
  std::ostringstream text;
  text << path << ": read as diffusion, " << out.indefinite << " of " << out.with_data << " voxels with data ("
       << percent(out.indefinite) << ") hold a tensor that is not positive definite (fitting noise)";
  if (out.speckle > 0)
    text << ", and " << out.speckle << " more (" << percent(out.speckle)
         << ") stand alone among those, as a background of noise does";
  text << ": left out as no data (data.quantity = \"stress\" reads them all)";
  return text.str();
}

}  // namespace hsb
