#include "renderer/app/batch.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <iterator>
#include <limits>
#include <optional>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "base/input_file.h"
#include "field/reading/vtk_data.h"
#include "renderer/scene/scene_spec.h"
#include "renderer/scene/toml_text.h"

namespace hsb {
namespace {

// The scene file's [sweep] table, as (key, values, where) in file order;
// none for data files and unreadable scenes.
struct SceneSweep {
  std::string key;
  std::vector<std::string> values;
  std::string where;                // file:line:column of the key's values
  std::vector<std::string> places;  // of each value
};

std::string place(const std::string& scene, const toml::node& node) {
  return scene + ":" + std::to_string(node.source().begin.line) + ":" + std::to_string(node.source().begin.column);
}

// The scene file's TOML, read once for the batch; none for data files and
// scenes that cannot be read or parsed (a FIFO would block the read):
// those are reported, with their line and column, when they render.
std::optional<toml::table> scene_root(const std::string& scene) {
  if (is_data_file(scene) || !unreadable_input(scene).empty()) return std::nullopt;
  try {
    return toml::parse_file(scene);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::vector<SceneSweep> scene_sweeps(const std::string& scene, const toml::table& root) {
  std::vector<SceneSweep> out;
  // "glyphs.spacing" = [...] and [sweep.glyphs] spacing = [...] say the same.
  if (const toml::table* sweep = root["sweep"].as_table())
    for_each_leaf(*sweep, "", [&](const std::string& path, const toml::node& node) {
      SceneSweep swept{path, {}, place(scene, node), {}};
      if (const toml::array* values = node.as_array()) {
        for (const toml::node& v : *values) {
          swept.values.push_back(toml_text(v));
          swept.places.push_back(place(scene, v));
        }
      } else {
        swept.values.push_back(toml_text(node));
        swept.places.push_back(place(scene, node));
      }
      out.push_back(std::move(swept));
    });
  return out;
}

// The data file a scene reads: the scene itself for a data file, else its
// data.file (a --set value over the file's), relative to the scene; ""
// when it names none or cannot be read (reported when it renders).
std::string data_file_of(const std::string& scene, const std::optional<toml::table>& root,
                         const std::vector<std::string>& fixed) {
  if (is_data_file(scene)) return scene;
  if (!root) return "";
  std::string file = (*root)["data"]["file"].value_or(std::string());
  for (const std::string& o : fixed)
    if (o.rfind("data.file=", 0) == 0) {
      file = o.substr(10);
      if (file.size() >= 2 && (file.front() == '"' || file.front() == '\'')) file = file.substr(1, file.size() - 2);
    }
  if (file.empty() || std::filesystem::path(file).is_absolute()) return file;
  return (std::filesystem::path(scene).parent_path() / file).lexically_normal().string();
}

// A swept value as it stands in an image's name: a TOML string without its
// quotes, as --set takes a bare word, so that --set color.map=magma and a
// [sweep] table's "color.map" = ["magma"] both name it color.map=magma
// (the table's TOML text, 'magma', once became color.map=_magma_);
// anything else (numbers, arrays) as written.
std::string value_in_name(const std::string& value) {
  if (value.empty() || (value.front() != '"' && value.front() != '\'')) return value;
  try {
    const toml::table parsed = toml::parse("v = " + value);
    if (const toml::value<std::string>* text = parsed["v"].as_string()) return text->get();
  } catch (const toml::parse_error&) {
    // Not one TOML string ("a" "b"): named as written.
  }
  return value;
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

Batch::Batch(const std::vector<std::string>& scenes, const std::vector<std::string>& overrides, bool as_series)
    : as_series_(as_series) {
  // The --set sweeps, in order; plain --set values stay as they are.
  std::vector<SweptKey> cli;
  for (const std::string& o : overrides) {
    const std::size_t eq = o.find('=');
    const std::vector<std::string> values =
        eq == std::string::npos ? std::vector<std::string>{} : split_sweep(o.substr(eq + 1));
    if (values.size() > 1)
      cli.push_back({o.substr(0, eq), values, {}});
    else
      fixed_.push_back(o);
  }
  for (const std::string& path : scenes) {
    Scene scene{path, cli, "", size_, 1};
    const std::optional<toml::table> root = scene_root(path);
    for (SceneSweep& s : root ? scene_sweeps(path, *root) : std::vector<SceneSweep>{}) {
      if (s.values.empty() && scene.error.empty())
        scene.error = s.where + ": sweep." + s.key + " lists no values; a sweep needs one or more";
      scene.swept.push_back({std::move(s.key), std::move(s.values), std::move(s.places)});
    }
    // A time series whose step no one chose: one image per step.
    const bool step_given =
        (root && root->at_path("data.step")) ||
        std::any_of(scene.swept.begin(), scene.swept.end(), [](const SweptKey& k) { return k.key == "data.step"; }) ||
        std::any_of(fixed_.begin(), fixed_.end(), [](const std::string& o) { return o.rfind("data.step=", 0) == 0; });
    if (!step_given) {
      std::vector<double> times;
      try {
        times = series_times(data_file_of(path, root, fixed_));
      } catch (const std::exception&) {
        // Reported, naming the file, when the scene is rendered.
      }
      SweptKey steps{"data.step", {}, {}};
      for (std::size_t i = 0; i < times.size(); ++i) steps.values.push_back(std::to_string(i));
      if (!steps.values.empty()) {
        scene.swept.insert(scene.swept.begin(), std::move(steps));
        scene.series = true;
      }
    }
    if (scene.error.empty())
      for (const SweptKey& k : scene.swept) {
        if (k.values.size() > std::numeric_limits<std::size_t>::max() / scene.count)
          throw std::invalid_argument(path + ": its sweeps ask for more images than can be counted");
        scene.count *= k.values.size();
      }
    if (scene.count > std::numeric_limits<std::size_t>::max() - size_)
      throw std::invalid_argument("the batch asks for more images than can be counted");
    size_ += scene.count;
    scenes_.push_back(std::move(scene));
  }
  // The steps of a --series pair up item by item (step 1's first sweep
  // value with step 2's), so each scene must make as many images.
  if (as_series_)
    for (const Scene& s : scenes_)
      if (s.error.empty() && s.count != scenes_.front().count && scenes_.front().error.empty())
        throw std::invalid_argument("--series: " + scenes_.front().path + " makes " +
                                    std::to_string(scenes_.front().count) + " images but " + s.path + " makes " +
                                    std::to_string(s.count) +
                                    "; the steps of a series must sweep the same values");
}

BatchItem Batch::item(std::size_t position) const {
  const auto after = std::upper_bound(scenes_.begin(), scenes_.end(), position,
                                      [](std::size_t p, const Scene& s) { return p < s.first; });
  const Scene& scene = *std::prev(after);
  BatchItem item{scene.path, fixed_, "", scene.error};
  if (!scene.error.empty()) return item;
  item.overrides = overrides_at(scene, position - scene.first, &item);
  if (scene.series || as_series_) item.series = series_of(scene, position - scene.first);
  return item;
}

std::vector<std::string> Batch::overrides_at(const Scene& scene, std::size_t offset, BatchItem* item) const {
  // The offset in mixed radix, the last key fastest. The overrides keep
  // each value's TOML text; the variant names it as --set would.
  std::vector<std::string> assignments(scene.swept.size()), names(scene.swept.size());
  for (std::size_t k = scene.swept.size(); k-- > 0;) {
    const SweptKey& swept = scene.swept[k];
    const std::size_t v = offset % swept.values.size();
    assignments[k] = swept.key + "=" + swept.values[v];
    if (item) names[k] = swept.key + "=" + value_in_name(swept.values[v]);
    if (item && !swept.where.empty()) item->sweep_origins.emplace_back(assignments[k], swept.where[v]);
    offset /= swept.values.size();
  }
  std::vector<std::string> overrides = fixed_;
  for (std::size_t k = 0; k < assignments.size(); ++k) {
    overrides.push_back(assignments[k]);
    if (item) item->variant += (item->variant.empty() ? "" : ",") + names[k];
  }
  return overrides;
}

std::vector<SeriesMember> Batch::series_of(const Scene& scene, std::size_t offset) const {
  std::vector<SeriesMember> members;
  const auto add_steps = [&](const Scene& s) {
    const std::vector<std::string> overrides = overrides_at(s, offset, nullptr);
    if (!s.series) {
      members.push_back({s.path, overrides});
      return;
    }
    // The same item at every step: its data.step assignment (the first
    // swept, after the fixed values) replaced.
    for (const std::string& step : s.swept.front().values) {
      SeriesMember member{s.path, overrides};
      member.overrides[fixed_.size()] = "data.step=" + step;
      members.push_back(std::move(member));
    }
  };
  if (!as_series_) {
    add_steps(scene);
    return members;
  }
  // Scenes that cannot be read render (and fail) on their own; the rest
  // share what the readable ones give.
  for (const Scene& s : scenes_)
    if (s.error.empty()) add_steps(s);
  return members;
}

std::string located_error(const BatchItem& item, const std::string& message) {
  for (const auto& [text, where] : item.sweep_origins) {
    const std::string prefix = "--set " + text + ": ";
    if (message.rfind(prefix, 0) == 0) return where + ": in [sweep], " + message.substr(prefix.size());
  }
  return message;
}

std::size_t Batch::shard_size(Shard shard) const {
  const std::size_t first = std::size_t(shard.index - 1), n = std::size_t(shard.count);
  return size_ > first ? (size_ - first - 1) / n + 1 : 0;
}

std::vector<BatchItem> expand_batch(const std::vector<std::string>& scenes, const std::vector<std::string>& overrides,
                                    bool as_series) {
  const Batch batch(scenes, overrides, as_series);
  std::vector<BatchItem> items;
  for (std::size_t i = 0; i < batch.size(); ++i) items.push_back(batch.item(i));
  return items;
}

Shard parse_shard(const std::string& text) {
  Shard shard;
  char slash = 0, rest = 0;
  std::istringstream in(text);
  if (!(in >> shard.index >> slash >> shard.count) || slash != '/' || (in >> rest) || shard.count < 1 ||
      shard.index < 1 || shard.index > shard.count)
    throw std::invalid_argument("--shard must be K/N with 1 <= K <= N (as in 3/8) or auto, got \"" + text + "\"");
  return shard;
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
