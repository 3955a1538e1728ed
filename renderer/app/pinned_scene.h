#pragma once
// A scene with every automatic value written out (hsb info): rendering it
// gives the same picture, and a user who likes a value can keep it while
// changing others.

#include <string>

#include "renderer/app/prepared_scene.h"

namespace hsb {

// TOML: the scene's own keys as it gives them, plus each automatic key with
// the value prepare_scene() resolved, and a comment naming the automatic
// keys. Relative paths stay as the scene gives them.
std::string pinned_scene_toml(const PreparedScene& prepared);

}  // namespace hsb
