#include "renderer/app/batch.h"

#include <toml++/toml.h>

#include <cctype>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "renderer/scene/scene_spec.h"
#include "renderer/scene/toml_text.h"

namespace hsb {
namespace {

struct SweptKey {
  std::string key;
  std::vector<std::string> values;  // each as TOML text
};

// The scene file's [sweep] table; none for data files and unreadable scenes.
std::vector<SweptKey> scene_sweeps(const std::string& scene) {
  std::vector<SweptKey> out;
  if (is_data_file(scene)) return out;
  try {
    const toml::table root = toml::parse_file(scene);
    // "glyphs.spacing" = [...] and [sweep.glyphs] spacing = [...] say the same.
    if (const toml::table* sweep = root["sweep"].as_table())
      for_each_leaf(*sweep, "", [&](const std::string& path, const toml::node& node) {
        SweptKey swept{path, {}};
        if (const toml::array* values = node.as_array())
          for (const toml::node& v : *values) swept.values.push_back(toml_text(v));
        else
          swept.values.push_back(toml_text(node));
        out.push_back(std::move(swept));
      });
  } catch (const std::exception&) {
    // Reported, with its line and column, when the scene is rendered.
  }
  return out;
}

}  // namespace

std::vector<std::string> split_sweep(const std::string& value) {
  std::vector<std::string> parts;
  std::string current;
  int depth = 0;
  char quote = 0;
  for (char c : value) {
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
    } else if (c == ',' && depth == 0) {
      parts.push_back(current);
      current.clear();
      continue;
    }
    current += c;
  }
  parts.push_back(current);
  return parts;
}

std::vector<BatchItem> expand_batch(const std::vector<std::string>& scenes, const std::vector<std::string>& overrides) {
  // The --set sweeps, in order; plain --set values stay as they are.
  std::vector<std::string> fixed;
  std::vector<SweptKey> cli;
  for (const std::string& o : overrides) {
    const std::size_t eq = o.find('=');
    const std::vector<std::string> values = eq == std::string::npos ? std::vector<std::string>{} : split_sweep(o.substr(eq + 1));
    if (values.size() > 1)
      cli.push_back({o.substr(0, eq), values});
    else
      fixed.push_back(o);
  }
  std::vector<BatchItem> items;
  for (const std::string& scene : scenes) {
    std::vector<SweptKey> swept = cli;
    for (SweptKey& s : scene_sweeps(scene)) swept.push_back(std::move(s));
    // Every combination, the last key changing fastest.
    std::vector<std::size_t> at(swept.size(), 0);
    for (;;) {
      BatchItem item{scene, fixed, ""};
      for (std::size_t k = 0; k < swept.size(); ++k) {
        const std::string assignment = swept[k].key + "=" + swept[k].values[at[k]];
        item.overrides.push_back(assignment);
        item.variant += (item.variant.empty() ? "" : ",") + assignment;
      }
      items.push_back(std::move(item));
      std::size_t k = swept.size();
      while (k > 0 && ++at[k - 1] == swept[k - 1].values.size()) at[--k] = 0;
      if (k == 0) break;
    }
  }
  return items;
}

Shard parse_shard(const std::string& text) {
  Shard shard;
  char slash = 0, rest = 0;
  std::istringstream in(text);
  if (!(in >> shard.index >> slash >> shard.count) || slash != '/' || (in >> rest) || shard.count < 1 ||
      shard.index < 1 || shard.index > shard.count)
    throw std::invalid_argument("--shard must be K/N with 1 <= K <= N (as in 3/8), got \"" + text + "\"");
  return shard;
}

std::vector<BatchItem> shard_items(const std::vector<BatchItem>& items, Shard shard) {
  std::vector<BatchItem> mine;
  for (std::size_t i = std::size_t(shard.index - 1); i < items.size(); i += std::size_t(shard.count))
    mine.push_back(items[i]);
  return mine;
}

std::string file_for_variant(const std::string& file, const std::string& variant) {
  if (variant.empty()) return file;
  std::string safe;
  for (char c : variant)
    safe += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '=' || c == '+' || c == '-' || c == ',')
                ? c
                : '_';
  const std::filesystem::path p(file);
  return (p.parent_path() / (p.stem().string() + "_" + safe + p.extension().string())).string();
}

}  // namespace hsb
