#pragma once
// The error for unusable data: a file that cannot be read, a missing or
// malformed tensor array, a NaN. Its message names the file and the point or
// cell, ready to print.

#include <stdexcept>

namespace hsb {

class DataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hsb
