#pragma once
// The one error type for bad scene input. Its message is complete and ready
// to print: "scenes/x.toml:12:5: glyphs.spacing must be > 0, got -0.1".

#include <stdexcept>
#include <string>

namespace hsb {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hsb
