#pragma once
// The scene file's schema: every key, once, with its type, range, default
// (or how it is chosen when left automatic), unit and a line of
// documentation. The reader takes ranges and defaults from here, --set and
// [sweep] check their keys against it, `hsb info` pins the automatic keys
// it lists, `hsb keys` prints it, and a test holds scenes/README.md to it.

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

namespace hsb {

// Allowed range of a number; lo_open makes the lower bound exclusive.
// Infinite values (TOML's inf) are refused unless allow_infinite is set;
// NaN is always refused.
struct NumberRange {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool allow_infinite = false;
};

enum class KeyType {
  number,
  integer,
  boolean,
  string,       // free text or a file name
  choice,       // one of KeySchema::choices
  view,         // one of KeySchema::choices, or a direction
  vector,       // [x, y, z], each within ±1e17 (a point, or an edge)
  direction,    // a vector, not zero
  color,        // [r, g, b] in [0, 1] or "#rrggbb"
  numbers,      // exactly KeySchema::count numbers
  points,       // [[x, y, z], ...]
  strings,      // an array of strings
  tables,       // an array of tables ([[seeds.grid]])
};

// Where a key's value comes from when the scene leaves it out.
enum class KeyDefault {
  value,      // KeySchema::fallback, as TOML text
  automatic,  // resolved from the data and the other keys (KeySchema::rule); `hsb info` pins it
  derived,    // follows another key, not from the data (KeySchema::rule)
  none,       // absent means none or off (KeySchema::rule says what)
};

// Lengths in the data's units, allowed between these multiples of the
// data's diagonal D: a shorter one is below the ray tracer's single
// precision, a longer one is not a length of this data set (a scale meant
// for other units).
inline constexpr double kSmallestLengthPerDiagonal = 1e-9;
inline constexpr double kLargestLengthPerDiagonal = 1e6;

struct KeySchema {
  std::string path;  // "glyphs.spacing"; keys of [[seeds.grid]] as "seeds.grid.n"
  KeyType type = KeyType::number;
  NumberRange range;  // numbers and integers; each element of numbers
  std::size_t count = 0;  // numbers: how many (0: any)
  std::vector<std::string> choices;  // choice: the names
  KeyDefault default_kind = KeyDefault::value;
  std::string fallback;  // value: the default as TOML text
  std::string rule;      // automatic, derived, none: in words
  // "data length" (checked against the data's diagonal once it is read),
  // "degrees", "mm", "points", "pixels", "fraction of white", or "".
  std::string unit;
  std::string doc;  // one line
  bool data_length() const { return unit == "data length"; }
};

// Every key, in the order of scenes/README.md.
const std::vector<KeySchema>& scene_keys();

// The key at `path` ("render.width", "seeds.grid.n"); nullptr if none.
const KeySchema* find_scene_key(std::string_view path);

// The key at `path`; throws std::logic_error if there is none (a reader
// asking for a key the schema does not list is the program's mistake).
const KeySchema& scene_key(std::string_view path);

// Whether `path` names a key or a table of keys ("glyphs", "light.ambient_occlusion").
bool is_scene_table(std::string_view path);

// "; did you mean glyphs.spacing?" for a near miss of a key, else "".
std::string nearest_key_hint(std::string_view path);

// The key's default as a TOML node (KeyDefault::value), else nullptr.
const toml::node* default_node(const KeySchema& key);

// The range as words: "> 0", "in [0, 1]", "any number".
std::string range_text(const KeySchema& key);

// The allowed values as words, for `hsb keys`: the range, the choices, …
std::string values_text(const KeySchema& key);

// The type as words: "number", "[x, y, z]", …
std::string type_text(const KeySchema& key);

}  // namespace hsb
