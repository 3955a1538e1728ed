#pragma once
// A scene with every automatic value written out (hsb info): rendering it
// gives the same picture, and a user who likes a value can keep it while
// changing others.

#include <string>
#include <vector>

#include "renderer/library/prepared_scene.h"

namespace hsb {

// The automatic keys (scene_keys.h) the scene leaves out that apply to it,
// in the schema's order.
std::vector<std::string> automatic_keys(const PreparedScene& prepared);

// TOML: the scene's own keys as it gives them, plus each automatic key with
// the value prepare_scene() resolved, and a comment naming the automatic
// keys. Relative paths stay as the scene gives them.
std::string pinned_scene_toml(const PreparedScene& prepared);

}  // namespace hsb
