#pragma once
// A value's bits read as another type of the same size (C++20's
// std::bit_cast, which C++17 lacks): for arithmetic on a float's bits.

#include <cstring>
#include <type_traits>

namespace hsb {

template <class To, class From>
inline To bit_cast(const From& from) {
  static_assert(sizeof(To) == sizeof(From), "bit_cast between types of one size");
  static_assert(std::is_trivially_copyable_v<To> && std::is_trivially_copyable_v<From>, "bit_cast of plain values");
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}

}  // namespace hsb
