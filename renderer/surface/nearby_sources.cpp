#include "renderer/surface/nearby_sources.h"

namespace hsb {

void NearbySources::clear() {
  used_chunks_ = 0;
  size_ = 0;
}

void NearbySources::add(const BlobField& field, std::uint32_t index, std::uint32_t rank, const Box3& influence) {
  const BlobSource& source = field.sources[index];
  if (size_ == used_chunks_ * kMaxPacket) {
    if (used_chunks_ == chunks_.size()) {
      chunks_.emplace_back();
      chunk_bounds_.emplace_back();
    }
    // Empty lanes hold W = 0: no ray enters them, and no NaN or denormal
    // slows the lane arithmetic down.
    chunks_[used_chunks_] = SourceLanes{};
    chunk_bounds_[used_chunks_++] = influence;
  }
  chunk_bounds_[used_chunks_ - 1].extend(influence);
  if (boxes_.size() == size_) boxes_.emplace_back();
  boxes_[size_] = influence;
  shape_ = field.shape;
  SourceLanes& chunk = chunks_[used_chunks_ - 1];
  const int lane = chunk.count++;
  for (int k = 0; k < 9; ++k) chunk.w[k][lane] = source.w[std::size_t(k)];
  for (int k = 0; k < 3; ++k) chunk.c[k][lane] = source.centre[std::size_t(k)];
  const ShapeSupport support = source_support(field, index);
  chunk.set_support(lane, support);
  chunk.boxed = !shape_is_quadric(field.shape);
  chunk.pointed |= support.pointed;
  chunk.index[lane] = index;
  chunk.rank[lane] = rank;
  ++size_;
}

void NearbySources::collect_spans(const Vec3& o, const Vec3& d, double tmin, double tmax,
                                  std::vector<RaySpan>& spans) const {
  SpanLanes lanes;
  for (std::size_t c = 0; c < used_chunks_; ++c) {
    const auto [t0, t1] = ray_interval_in(chunk_bounds_[c], o, d, tmin, tmax);
    if (!(t0 <= t1)) continue;
    const SourceLanes& chunk = chunks_[c];
    for (unsigned entered = source_spans(chunk, o, d, tmin, tmax, lanes); entered; entered &= entered - 1) {
      const int i = __builtin_ctz(entered);
      lanes.append(i, chunk.index[i], chunk.rank[i], spans);
      if (!narrow_to_influence(shape_, boxes_[c * kMaxPacket + std::size_t(i)], o, d, spans.back())) spans.pop_back();
    }
  }
}

}  // namespace hsb
