#pragma once
// Typed, validated access to one TOML table of a scene file. Every read
// names the key, so when a value has the wrong type or range the error
// names the file, line, column and full key path; keys nobody read are
// reported by finish() as unknown (they are usually typos).

#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "field/sym3.h"
#include "renderer/render/shading.h"
#include "renderer/scene/scene_error.h"

namespace hsb {

// "file:line:column" of a node ("--set key=value" for command-line values).
std::string source_location(const toml::node& node);
std::string source_location(const toml::source_region& where);

// Allowed range of a number; lo_open makes the lower bound exclusive.
// Infinite values (TOML's inf) are refused unless allow_infinite is set;
// NaN is always refused.
struct NumberRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool allow_infinite = false;
};
inline constexpr NumberRange any_number{};
inline constexpr NumberRange positive{0.0, std::numeric_limits<double>::infinity(), true};
inline constexpr NumberRange non_negative{0.0, std::numeric_limits<double>::infinity(), false};
inline constexpr NumberRange positive_or_infinite{0.0, std::numeric_limits<double>::infinity(), true, true};

class TableReader {
 public:
  // `prefix` is the key path of this table, e.g. "glyphs" ("" for the root);
  // `where` is the location to blame for a missing required key.
  TableReader(const toml::table& table, std::string prefix, std::string where);

  double number(std::string_view key, double fallback, NumberRange range = any_number);
  // The same, nullopt when absent: an automatic value.
  std::optional<double> optional_number(std::string_view key, NumberRange range = any_number);
  std::optional<bool> optional_boolean(std::string_view key);
  std::optional<std::string> optional_string(std::string_view key);
  int integer(std::string_view key, int fallback, int lo = std::numeric_limits<int>::min(),
              int hi = std::numeric_limits<int>::max());
  bool boolean(std::string_view key, bool fallback);
  std::string string(std::string_view key, const std::string& fallback);
  Vec3 vec3(std::string_view key, const Vec3& fallback);
  // A point in space: [x, y, z] with every coordinate within ±1e17. The
  // ray tracer keeps rays in single precision, so nothing farther can be
  // traced, and points near the double range overflow every length
  // computed from them.
  Vec3 position(std::string_view key, const Vec3& fallback);
  // [r, g, b] with components in [0, 1] or "#rrggbb".
  Rgb color(std::string_view key, const Rgb& fallback);
  // Numbers, exactly `count` of them (any count when count is 0).
  std::vector<double> numbers(std::string_view key, std::size_t count);
  // An array of points, each as position() requires (empty when absent).
  std::vector<Vec3> points(std::string_view key);
  // An array of strings (empty when absent).
  std::vector<std::string> strings(std::string_view key);

  // One of a fixed set of names, mapped to a value.
  template <class T>
  T choice(std::string_view key, T fallback,
           std::initializer_list<std::pair<const char*, T>> options);
  template <class T>
  T choice(std::string_view key, T fallback, const std::vector<std::pair<std::string, T>>& options);

  // A sub-table (nullopt when absent) and an array of tables.
  std::optional<TableReader> table(std::string_view key);
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
  std::string choice_error(const std::vector<std::string>& names) const;

  const toml::table& table_;
  std::string prefix_, where_;
  std::set<std::string, std::less<>> known_;
};

// Prints a node's value for error messages ("string \"abc\"", "-0.1").
std::string describe(const toml::node& node);

template <class T>
T TableReader::choice(std::string_view key, T fallback,
                      std::initializer_list<std::pair<const char*, T>> options) {
  std::vector<std::pair<std::string, T>> named;
  for (const auto& option : options) named.emplace_back(option.first, option.second);
  return choice(key, fallback, named);
}

template <class T>
T TableReader::choice(std::string_view key, T fallback, const std::vector<std::pair<std::string, T>>& options) {
  const toml::node* node = lookup(key);
  if (!node) return fallback;
  std::vector<std::string> names;
  for (const auto& option : options) names.push_back(option.first);
  if (const auto* s = node->as_string()) {
    for (const auto& option : options)
      if (s->get() == option.first) return option.second;
  }
  fail(*node, key, choice_error(names) + ", got " + describe(*node));
}

}  // namespace hsb
