// libFuzzer target: scene text, as a user might mistype it. Any input must
// give a SceneSpec or one SceneError/DataError: never a crash, a hang, an
// uncaught exception or undefined behaviour.

#include <cstddef>
#include <cstdint>
#include <string>

#include "field/reading/data_error.h"
#include "renderer/scene/scene_error.h"
#include "renderer/scene/scene_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // Relative data files resolve against the seed corpus folder, where a
    // small data set lies, so the fuzzer can reach the VTK keys too.
    hsb::load_scene_text(text, "fuzz.toml", HSB_FUZZ_DATA_DIR, {"render.width=8"});
  } catch (const hsb::SceneError&) {
  } catch (const hsb::DataError&) {
  }
  return 0;
}
