#pragma once
// Axis-aligned box, used for data-set domains and bounds.

#include <array>

#include "field/sym3.h"

namespace hsb {

struct Box3 {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();

  bool contains(const Vec3& p) const {
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
  }
  Vec3 size() const { return hi - lo; }
  Vec3 centre() const { return 0.5 * (lo + hi); }
  double diagonal() const { return size().norm(); }
  std::array<Vec3, 8> corners() const {
    std::array<Vec3, 8> c;
    for (int i = 0; i < 8; ++i)
      c[std::size_t(i)] = Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
    return c;
  }
};

}  // namespace hsb
