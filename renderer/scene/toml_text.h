#pragma once
// TOML values as text that --set reads back, values put at dotted key
// paths, and tables flattened to dotted key paths: how a [sweep] table and a [[panel]] table turn into
// overrides of the scene they belong to.

#include <toml++/toml.h>

#include <functional>
#include <string>
#include <string_view>

namespace hsb {

// A value as TOML text; a number as short as it was written (0.1, not
// 0.10000000000000001), since it may name an image.
std::string toml_text(const toml::node& node);

// Calls `leaf(path, node)` for every value under `table` that is not
// itself a table, its path dotted from `prefix` ("glyphs.spacing" = 0.1
// and [x.glyphs] spacing = 0.1 give the same path), in the order the
// values appear in the file (toml++ keeps tables sorted by key).
void for_each_leaf(const toml::table& table, const std::string& prefix,
                   const std::function<void(const std::string& path, const toml::node& node)>& leaf);

// The table at dotted `path` in `root` ("" is root itself), with every
// missing table on the way created; nullptr when a value that is not a
// table stands in the way.
toml::table* table_at_path(toml::table& root, std::string_view path);

// Puts `value` at dotted `path` in `root`, replacing what was there.
// Returns false when a value that is not a table stands in the way.
template <class V>
bool assign_at_path(toml::table& root, std::string_view path, V&& value) {
  const std::size_t dot = path.rfind('.');
  toml::table* table = dot == std::string_view::npos ? &root : table_at_path(root, path.substr(0, dot));
  if (!table) return false;
  table->insert_or_assign(path.substr(dot == std::string_view::npos ? 0 : dot + 1), std::forward<V>(value));
  return true;
}

}  // namespace hsb
