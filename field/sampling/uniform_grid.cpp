#include "field/sampling/uniform_grid.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hsb {

namespace {

std::size_t node_count(const std::array<int, 3>& dims) {
  return static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(dims[1]) *
         static_cast<std::size_t>(dims[2]);
}

void validate_dims(const std::array<int, 3>& dims) {
  for (int a = 0; a < 3; ++a) {
    if (dims[a] < 2)
      throw std::invalid_argument("uniform grid: dims[" + std::to_string(a) + "] = " +
                                  std::to_string(dims[a]) + ", every dimension must be >= 2");
  }
}

bool is_finite(const Sym3& v) { return v.is_finite(); }
bool is_finite(double v) { return std::isfinite(v); }
bool is_infinite(const Sym3& v) {
  return std::isinf(v.xx) || std::isinf(v.yy) || std::isinf(v.zz) || std::isinf(v.xy) || std::isinf(v.yz) ||
         std::isinf(v.xz);
}
bool is_infinite(double v) { return std::isinf(v); }

}  // namespace

template <class T>
UniformGrid<T>::UniformGrid(const Vec3& origin, const Vec3& spacing, const std::array<int, 3>& dims,
                            SharedValues<T> values, const Mat3& direction)
    : origin_(origin),
      spacing_(spacing),
      direction_(direction),
      aligned_(direction == Mat3::Identity()),
      dims_(dims),
      values_(std::move(values)) {
  if (!direction_.allFinite() || !(std::fabs(direction_.determinant()) > 1e-12))
    throw std::invalid_argument("uniform grid: the direction matrix must be finite and invertible");
  to_index_ = spacing_.cwiseInverse().asDiagonal() * direction_.inverse();
  validate_dims(dims_);
  if (!origin_.allFinite()) throw std::invalid_argument("uniform grid: origin must be finite");
  if (!spacing_.allFinite() || !(spacing_.array() > 0.0).all())
    throw std::invalid_argument("uniform grid: spacing must be finite and > 0 on every axis");
  if (values_.size() != node_count(dims_))
    throw std::invalid_argument("uniform grid: got " + std::to_string(values_.size()) +
                                " values for " + std::to_string(dims_[0]) + "x" +
                                std::to_string(dims_[1]) + "x" + std::to_string(dims_[2]) +
                                " = " + std::to_string(node_count(dims_)) + " nodes");
  // A NaN node is no data (sample() gives nothing around it); an infinite
  // one would make every sample near it infinite. Looked for on every
  // core: a diffusion volume has millions of nodes.
  const std::vector<T>& nodes = values_.vector();
  const bool infinite = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, nodes.size(), std::size_t(1) << 16), false,
      [&](const tbb::blocked_range<std::size_t>& range, bool found) {
        for (std::size_t i = range.begin(); i < range.end() && !found; ++i) found = is_infinite(nodes[i]);
        return found;
      },
      [](bool a, bool b) { return a || b; });
  if (infinite) throw std::invalid_argument("uniform grid: infinite value");
}

template <class T>
UniformGrid<T> UniformGrid<T>::sampled_from(const Field<T>& field, const std::array<int, 3>& dims) {
  validate_dims(dims);
  const Box3 b = field.bounds();
  const Vec3 spacing = b.size().cwiseQuotient(
      Vec3(dims[0] - 1, dims[1] - 1, dims[2] - 1));

  std::vector<T> values;
  values.reserve(node_count(dims));
  for (int k = 0; k < dims[2]; ++k) {
    for (int j = 0; j < dims[1]; ++j) {
      for (int i = 0; i < dims[0]; ++i) {
        // Blend the corners rather than stepping origin + i·spacing, so the
        // last node is exactly on the far face and never outside the
        // field's domain by a rounding error.
        const Vec3 t(static_cast<double>(i) / (dims[0] - 1),
                     static_cast<double>(j) / (dims[1] - 1),
                     static_cast<double>(k) / (dims[2] - 1));
        const Vec3 p = ((Vec3::Ones() - t).cwiseProduct(b.lo) + t.cwiseProduct(b.hi))
                           .cwiseMax(b.lo)
                           .cwiseMin(b.hi);
        const std::optional<T> s = field.sample(p);
        if (!s)
          throw std::runtime_error("uniform grid: the field cannot be sampled at node (" +
                                   std::to_string(i) + ", " + std::to_string(j) + ", " +
                                   std::to_string(k) + ")");
        values.push_back(*s);
      }
    }
  }
  return UniformGrid(b.lo, spacing, dims, std::move(values));
}

template <class T>
Box3 UniformGrid<T>::bounds() const {
  const Vec3 extent = spacing_.cwiseProduct(Vec3(dims_[0] - 1, dims_[1] - 1, dims_[2] - 1));
  if (aligned_) return {origin_, origin_ + extent};
  Box3 box{origin_, origin_};
  for (int corner = 1; corner < 8; ++corner) {
    const Vec3 p = origin_ + direction_ * Vec3(corner & 1 ? extent.x() : 0.0, corner & 2 ? extent.y() : 0.0,
                                               corner & 4 ? extent.z() : 0.0);
    box.lo = box.lo.cwiseMin(p), box.hi = box.hi.cwiseMax(p);
  }
  return box;
}

template <class T>
const T& UniformGrid<T>::node(int i, int j, int k) const {
  const std::size_t index =
      static_cast<std::size_t>(i) +
      static_cast<std::size_t>(dims_[0]) *
          (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims_[1]) * k);
  return values_.at(index);
}

template <class T>
std::optional<T> UniformGrid<T>::sample(const Vec3& x) const {
  // Work in index space. A point is inside when its index coordinate lies in
  // [0, dims−1]; a relative slack of a few ulps admits points that are on
  // the far face in world space but land a rounding error past it in index
  // space (origin + spacing·(dims−1) need not reproduce the face exactly).
  constexpr double kSlack = 1e-12;
  int cell[3];
  double t[3];
  const Vec3 index = aligned_ ? Vec3((x - origin_).cwiseQuotient(spacing_)) : Vec3(to_index_ * (x - origin_));
  for (int a = 0; a < 3; ++a) {
    const double u = index(a);
    const double last = dims_[a] - 1;
    if (!(u >= -kSlack * last && u <= last * (1.0 + kSlack))) return std::nullopt;  // NaN too
    // Clamping the cell to dims−2 puts the far face in the last cell (t = 1).
    const int c = std::clamp(static_cast<int>(std::floor(u)), 0, dims_[a] - 2);
    cell[a] = c;
    t[a] = std::clamp(u - c, 0.0, 1.0);
  }

  // Trilinear: blend the eight corners with weights that sum to one, so
  // affine component fields are reproduced exactly.
  T result{};
  for (int corner = 0; corner < 8; ++corner) {
    const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
    const double w = (di ? t[0] : 1.0 - t[0]) * (dj ? t[1] : 1.0 - t[1]) *
                     (dk ? t[2] : 1.0 - t[2]);
    result = result + w * node(cell[0] + di, cell[1] + dj, cell[2] + dk);
  }
  // A NaN node is no data (a masked voxel): its cells are outside.
  if (!is_finite(result)) return std::nullopt;
  return result;
}

template class UniformGrid<Sym3>;
template class UniformGrid<double>;

}  // namespace hsb
