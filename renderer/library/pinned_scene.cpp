#include "renderer/library/pinned_scene.h"

#include <filesystem>
#include <sstream>

#include "renderer/scene/scene_keys.h"
#include "renderer/scene/toml_text.h"

namespace hsb {

std::vector<std::string> automatic_keys(const PreparedScene& p) {
  const toml::table given = scene_table(p.spec);
  std::vector<std::string> keys;
  for (const KeySchema& key : scene_keys())
    if (key.default_kind == KeyDefault::automatic && p.resolved.at_path(key.path) && !given.at_path(key.path))
      keys.push_back(key.path);
  return keys;
}

std::string pinned_scene_toml(const PreparedScene& p) {
  toml::table root = scene_table(p.spec);
  const std::vector<std::string> automatic = automatic_keys(p);
  for (const std::string& key : automatic) {
    const toml::node* value = p.resolved.at_path(key).node();
    value->visit([&](const auto& v) { assign_at_path(root, key, v); });
  }
  const auto pinned = [&](std::string_view key) {
    return std::find(automatic.begin(), automatic.end(), key) != automatic.end();
  };
  // A data file given alone has no scene to be beside: its path is
  // written whole, so the scene renders wherever it is saved
  // (`hsb info FILE > dir/FILE.toml`).
  if (is_data_file(p.spec.path))
    assign_at_path(root, "data.file", std::filesystem::absolute(p.spec.pipeline.data.file.path).lexically_normal().string());
  // Automatic seeds are in the frame they were made in.
  if (pinned("seeds.grid") || pinned("seeds.points")) assign_at_path(root, "seeds.frame", *p.resolved.at_path("seeds.frame").value<std::string>());
  // With position and look_at fixed, view, frame and margin no longer
  // apply: left out, the pinned scene says what it does.
  if (pinned("camera.position") || pinned("camera.look_at"))
    if (toml::table* camera = root["camera"].as_table())
      for (const char* moot : {"view", "frame", "margin"}) camera->erase(moot);

  std::ostringstream out;
  out << "# " << p.spec.path << " with every automatic value written out: save this as a scene\n"
      << "# (relative paths as in the original, so beside it; a data file's path is whole) and it\n"
      << "# renders the same picture.\n"
      << "# Automatic here:";
  for (const std::string& key : automatic) out << " " << key;
  out << "\n" << toml::toml_formatter(root) << "\n";
  return out.str();
}

}  // namespace hsb
