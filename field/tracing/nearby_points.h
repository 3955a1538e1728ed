#pragma once
// Points of the trajectories traced so far, hashed into cubic cells, so
// "is any point within r of x?" costs the few cells around x, not a scan:
// the question evenly spaced seeding asks at every integration step.

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "base/vec3.h"

namespace hsb {

class NearbyPoints {
 public:
  // Queries up to about `cell` away are cheapest; larger ones still work.
  explicit NearbyPoints(double cell);

  // `tag` says whose point it is (a trajectory's index, an arc length).
  void add(const Vec3& p, double tag = 0.0);

  // The distance from `x` to the nearest point within `radius` whose tag
  // the predicate accepts; `radius` itself when there is none.
  template <class Accept>
  double nearest(const Vec3& x, double radius, Accept&& accept) const {
    double best2 = radius * radius;
    const int reach = int(std::ceil(radius / cell_));
    const Key c = key_of(x);
    for (int i = -reach; i <= reach; ++i)
      for (int j = -reach; j <= reach; ++j)
        for (int k = -reach; k <= reach; ++k) {
          const auto found = cells_.find(pack(c.x + i, c.y + j, c.z + k));
          if (found == cells_.end()) continue;
          for (const Entry& e : found->second) {
            const double d2 = (e.p - x).squaredNorm();
            if (d2 < best2 && accept(e.tag)) best2 = d2;
          }
        }
    return std::sqrt(best2);
  }
  double nearest(const Vec3& x, double radius) const {
    return nearest(x, radius, [](double) { return true; });
  }

  std::size_t size() const { return count_; }

 private:
  struct Key {
    std::int64_t x, y, z;
  };
  struct Entry {
    Vec3 p;
    double tag;
  };
  Key key_of(const Vec3& p) const;
  static std::uint64_t pack(std::int64_t x, std::int64_t y, std::int64_t z);

  double cell_;
  std::unordered_map<std::uint64_t, std::vector<Entry>> cells_;
  std::size_t count_ = 0;
};

}  // namespace hsb
