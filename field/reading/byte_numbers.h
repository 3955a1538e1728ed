#pragma once
// Numbers stored as bytes in a file's own byte order, for the readers hsb
// writes itself (NRRD, MRtrix, CalculiX's binary results).

#include <algorithm>
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

}  // namespace hsb
