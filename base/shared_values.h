#pragma once
// A read-only array of values that several owners hold at once: a data
// set's tensors are both the field sampled between the points and the
// sites a glyph field draws at each point, and a second copy of a large
// volume's tensors (33 MB for 88³ voxels) would only raise the peak memory.

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace hsb {

template <class T>
class SharedValues {
 public:
  SharedValues() = default;
  // Takes the values over (implicit, so a vector goes where values do).
  SharedValues(std::vector<T> values) : values_(std::make_shared<const std::vector<T>>(std::move(values))) {}

  const std::vector<T>& vector() const { return values_ ? *values_ : empty_; }
  std::size_t size() const { return vector().size(); }
  bool empty() const { return vector().empty(); }
  const T& operator[](std::size_t i) const { return vector()[i]; }
  const T& at(std::size_t i) const { return vector().at(i); }
  typename std::vector<T>::const_iterator begin() const { return vector().begin(); }
  typename std::vector<T>::const_iterator end() const { return vector().end(); }

 private:
  std::shared_ptr<const std::vector<T>> values_;
  static inline const std::vector<T> empty_{};
};

}  // namespace hsb
