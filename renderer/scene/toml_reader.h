#pragma once
// Typed, validated access to one TOML table of a scene file. Each key's
// type, range and default come from the schema (scene_keys.h): a read
// names only the key. When a value has the wrong type or range the error
// names the file, line, column and full key path; keys nobody read are
// reported by finish() as unknown (they are usually typos).

#include <initializer_list>
#include <stdexcept>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "base/vec3.h"
#include "renderer/render/shading.h"
#include "renderer/scene/scene_error.h"
#include "renderer/scene/scene_keys.h"

namespace hsb {

// "file:line:column" of a node ("--set key=value" for command-line values).
std::string source_location(const toml::node& node);
std::string source_location(const toml::source_region& where);

class TableReader {
 public:
  // `prefix` is the key path of this table, e.g. "glyphs" ("" for the root;
  // "seeds.grid[2]" for an element of an array of tables); `where` is the
  // location to blame for a missing required key.
  TableReader(const toml::table& table, std::string prefix, std::string where);

  // The key's value, else its schema default. Keys whose schema default
  // is automatic, derived or none are read as optionals: nullopt when
  // absent.
  double number(std::string_view key);
  std::optional<double> optional_number(std::string_view key);
  int integer(std::string_view key);
  std::optional<int> optional_integer(std::string_view key);
  bool boolean(std::string_view key);
  std::optional<bool> optional_boolean(std::string_view key);
  std::string string(std::string_view key);  // "" when absent without a default
  std::optional<std::string> optional_string(std::string_view key);
  // [x, y, z] with every coordinate within ±1e17 (not zero for a
  // direction). The ray tracer keeps rays in single precision, so nothing
  // farther can be traced, and points near the double range overflow
  // every length computed from them.
  Vec3 vector(std::string_view key);
  std::optional<Vec3> optional_vector(std::string_view key);
  // [r, g, b] with components in [0, 1] or "#rrggbb".
  Rgb color(std::string_view key);
  // Numbers, as many as the schema says, each in its range (empty when
  // absent without a default).
  std::vector<double> numbers(std::string_view key);
  // An array of points, each as vector() requires (empty when absent).
  std::vector<Vec3> points(std::string_view key);
  // An array of strings, each one of the schema's choices when it has any.
  std::vector<std::string> strings(std::string_view key);

  // One of the schema's names, mapped to a value: `options` maps every
  // name the schema lists. The default is the schema's, or `fallback` for
  // a key whose default follows another key.
  template <class T>
  T choice(std::string_view key, std::initializer_list<std::pair<const char*, T>> options);
  template <class T>
  T choice(std::string_view key, const std::vector<std::pair<std::string, T>>& options);
  template <class T>
  T choice(std::string_view key, T fallback, std::initializer_list<std::pair<const char*, T>> options);

  // A sub-table (empty when absent, so its keys take their defaults) and
  // an array of tables.
  TableReader table(std::string_view key);
  std::vector<TableReader> tables(std::string_view key);

  bool has(std::string_view key) const { return table_.contains(key); }
  bool holds_string(std::string_view key) const {
    const toml::node* node = table_.get(key);
    return node && node->is_string();
  }
  // A key read by someone else (hsb's batch reads [sweep]): not unknown.
  void allow(std::string_view key) { known_.emplace(key); }
  // Errors on the first key of this table that no read asked for.
  void finish() const;

  std::string path(std::string_view key) const;
  [[noreturn]] void fail(const toml::node& at, std::string_view key, const std::string& what) const;
  // The same, located at the key's value (or at this table when it is absent).
  [[noreturn]] void fail_at(std::string_view key, const std::string& what) const;

 private:
  const toml::node* lookup(std::string_view key);
  // The key's schema entry (its path without array indices).
  const KeySchema& schema(std::string_view key) const;
  // The value in the file, else the schema default, else nullptr.
  const toml::node* value_or_default(std::string_view key);
  std::optional<Vec3> read_vector(std::string_view key, const toml::node& node);
  std::string choice_error(const std::vector<std::string>& names) const;
  // The option named by the value, else by the schema default.
  template <class T>
  T chosen(std::string_view key, std::optional<T> fallback, const std::vector<std::pair<std::string, T>>& options);

  const toml::table& table_;
  std::string prefix_, schema_prefix_, where_;
  std::set<std::string, std::less<>> known_;
};

// Prints a node's value for error messages ("string \"abc\"", "-0.1").
std::string describe(const toml::node& node);

template <class T>
T TableReader::choice(std::string_view key, std::initializer_list<std::pair<const char*, T>> options) {
  std::vector<std::pair<std::string, T>> named;
  for (const auto& option : options) named.emplace_back(option.first, option.second);
  return chosen<T>(key, std::nullopt, named);
}

template <class T>
T TableReader::choice(std::string_view key, const std::vector<std::pair<std::string, T>>& options) {
  return chosen<T>(key, std::nullopt, options);
}

template <class T>
T TableReader::choice(std::string_view key, T fallback, std::initializer_list<std::pair<const char*, T>> options) {
  std::vector<std::pair<std::string, T>> named;
  for (const auto& option : options) named.emplace_back(option.first, option.second);
  return chosen<T>(key, fallback, named);
}

template <class T>
T TableReader::chosen(std::string_view key, std::optional<T> fallback,
                      const std::vector<std::pair<std::string, T>>& options) {
  const KeySchema& k = schema(key);
  std::vector<std::string> names;
  for (const auto& option : options) names.push_back(option.first);
  if (names != k.choices) throw std::logic_error("the reader's names for " + k.path + " differ from the schema's");
  const toml::node* node = lookup(key);
  if (!node && fallback) return *fallback;
  if (!node) node = default_node(k);
  if (!node) throw std::logic_error("the schema has no default for " + k.path);
  if (const auto* s = node->as_string()) {
    for (const auto& option : options)
      if (s->get() == option.first) return option.second;
  }
  fail(*node, key, choice_error(names) + ", got " + describe(*node));
}

}  // namespace hsb
