#pragma once
// Numbers stored as bytes in a file's own byte order, for the readers hsb
// writes itself (NRRD, MRtrix, CalculiX's binary results).

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace hsb {

// The number of type T at `bytes`, its bytes reversed where the file's
// byte order is not the machine's (`swap`).
template <typename T>
double load_number(const unsigned char* bytes, bool swap) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, bytes, sizeof(T));
  if (swap) std::reverse(b, b + sizeof(T));
  T t;
  std::memcpy(&t, b, sizeof t);
  return double(t);
}

// What a stored number is: a signed or an unsigned integer, or IEEE
// floating point.
enum class NumberKind { integer, unsigned_integer, floating };

// Calls `use(at)`, `at(e)` being element e of `data` as a double, with
// `at` made for numbers of `bytes` bytes of `kind` in the file's byte order
// (one loop compiled a type, not a call a value). False, calling nothing,
// for a type no reader makes (the readers refuse those as they parse).
template <class Use>
bool with_typed_numbers(const unsigned char* data, int bytes, NumberKind kind, bool swap, Use&& use) {
  const auto typed = [&](auto zero) {
    using T = decltype(zero);
    use([data, swap](std::uint64_t e) { return load_number<T>(data + e * sizeof(T), swap); });
    return true;
  };
  const bool floating = kind == NumberKind::floating, is_signed = kind == NumberKind::integer;
  switch (bytes) {
    case 1: return floating ? false : is_signed ? typed(std::int8_t{}) : typed(std::uint8_t{});
    case 2: return floating ? false : is_signed ? typed(std::int16_t{}) : typed(std::uint16_t{});
    case 4: return floating ? typed(float{}) : is_signed ? typed(std::int32_t{}) : typed(std::uint32_t{});
    case 8: return floating ? typed(double{}) : is_signed ? typed(std::int64_t{}) : typed(std::uint64_t{});
    default: return false;
  }
}

}  // namespace hsb
